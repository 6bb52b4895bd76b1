// Rendering in passes, and stopping, saving and resuming between them, sums
// the same samples in the same order as one uninterrupted render: the same bits.
#include <gtest/gtest.h>

#include <cstring>

#include "camera/pinhole_camera.h"
#include "render/film_state.h"
#include "render/lights.h"
#include "render/renderer.h"
#include "render/test_scene_util.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

struct Fixture {
  Fixture() {
    SceneDesc s;
    s.sourceFile = "sphere on plane (in code)";
    s.meshes.push_back(test::makeSphere({0, 1, 0}, 1, 12, 24));
    s.meshes.push_back(test::makeQuadY(0, 20));
    s.meshes[0].material = 0;
    s.meshes[1].material = 0;
    s.instances = {{0, Transform()}, {1, Transform()}};
    s.materials = {test::whiteMatte()};
    scene = std::make_unique<RenderScene>(std::move(s));
    materials = std::make_unique<MaterialTable>(scene->desc());
    lights = std::make_unique<LightSet>(*materials, environment, scene->bounds());
    integrator = std::make_unique<Integrator>(*scene, *materials, *lights, environment, IntegratorSettings{});
    settings.samplesPerPixel = 7;
    settings.seed = 5;
    settings.aovs = {true, true, true, true};
    // The coordinate AOVs' sums go with the others (resumes, strips).
    settings.aovs.position = settings.aovs.uv = settings.aovs.objectCoords = true;
    settings.tileSize = 6;
  }
  Environment environment = Environment::constant({0.5f, 0.7f, 1.0f});
  std::unique_ptr<RenderScene> scene;
  std::unique_ptr<MaterialTable> materials;
  std::unique_ptr<LightSet> lights;
  std::unique_ptr<Integrator> integrator;
  RenderSettings settings;
  PinholeCamera camera{Transform::lookAt({0, 2, 5}, {0, 1, 0}, {0, 1, 0}), {21, 13, 36, 24}, 0.8};
};

bool sameBits(const Image& a, const Image& b) {
  return a.channels == b.channels && a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(Passes, PassesStopsAndResumesGiveTheUninterruptedImage) {
  const Fixture f;
  const RenderOutput whole = renderImage(f.camera, *f.integrator, f.settings);

  // Passes of 1, 2, 4 spp; stopped after the second pass, saved as bytes and
  // continued from them.
  FilmState state(PixelRegion::wholeFrame(21, 13), f.settings.aovs);
  PassControl control;
  control.passSeconds = 1e9;  // always double: 1, 2, 4
  int passes = 0;
  control.stopRequested = [&] { return ++passes == 2; };
  EXPECT_FALSE(renderPasses(f.camera, *f.integrator, f.settings, state, &control));
  EXPECT_EQ(state.samplesDone(), 3);
  const std::vector<std::byte> saved = state.toBytes();
  FilmState resumed = FilmState::fromBytes(saved);
  EXPECT_EQ(resumed.samplesDone(), 3);
  control.stopRequested = nullptr;
  EXPECT_TRUE(renderPasses(f.camera, *f.integrator, f.settings, resumed, &control));
  EXPECT_EQ(resumed.samplesDone(), 7);
  const RenderOutput out = renderOutput(f.camera, resumed);
  EXPECT_TRUE(sameBits(out.image, whole.image));
  EXPECT_EQ(out.blockedCameraRays, whole.blockedCameraRays);
  EXPECT_EQ(out.cameraSamples, whole.cameraSamples);

  // Stopping early changes the image (the test can fail).
  const RenderOutput partial = renderOutput(f.camera, FilmState::fromBytes(saved));
  EXPECT_FALSE(sameBits(partial.image, whole.image));
}

TEST(Passes, ARegionIsThoseExactPixelsOfTheWholeFrame) {
  Fixture f;
  const RenderOutput whole = renderImage(f.camera, *f.integrator, f.settings);
  f.settings.region = PixelRegion{3, 17, 4, 9};
  const RenderOutput crop = renderImage(f.camera, *f.integrator, f.settings);
  const Image& c = crop.image;
  EXPECT_EQ(c.width, 14);
  EXPECT_EQ(c.height, 5);
  EXPECT_EQ(c.originX, 3);
  EXPECT_EQ(c.originY, 4);
  EXPECT_EQ(c.fullWidth(), 21);
  EXPECT_EQ(c.fullHeight(), 13);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x)
      for (int k = 0; k < int(c.channelCount()); ++k)
        ASSERT_EQ(c.at(x, y, k), whole.image.at(x + 3, y + 4, k)) << x << "," << y;
  f.settings.region = PixelRegion{3, 22, 4, 9};
  EXPECT_THROW(renderImage(f.camera, *f.integrator, f.settings), std::invalid_argument);
}

TEST(Passes, FrameStripsCoverTheFrameOnceInOrder) {
  for (const int count : {1, 3, 7, 13}) {
    int next = 0;
    for (int i = 0; i < count; ++i) {
      const PixelRegion r = frameStrip(i, count, 10, 13);
      EXPECT_EQ(r.y0, next);
      EXPECT_GE(r.height(), 13 / count);
      EXPECT_LE(r.height(), 13 / count + 1);
      EXPECT_EQ(r.x0, 0);
      EXPECT_EQ(r.x1, 10);
      next = r.y1;
    }
    EXPECT_EQ(next, 13);
  }
  EXPECT_THROW(frameStrip(0, 14, 10, 13), std::invalid_argument);
  EXPECT_THROW(frameStrip(3, 3, 10, 13), std::invalid_argument);
}

TEST(Passes, DamagedSumsAreRefused) {
  FilmState state(PixelRegion{0, 4, 0, 2}, AovSelection{});
  std::vector<std::byte> bytes = state.toBytes();
  EXPECT_NO_THROW(FilmState::fromBytes(bytes));
  EXPECT_THROW(FilmState::fromBytes(std::span(bytes).first(bytes.size() - 1)), std::invalid_argument);
  bytes[0] = std::byte{'X'};
  EXPECT_THROW(FilmState::fromBytes(bytes), std::invalid_argument);
  EXPECT_THROW(FilmState::fromBytes({}), std::invalid_argument);
  // Version 1 (before alpha's coverage counts) says so.
  const std::string version1 = "LRTSUMS1";
  std::memcpy(bytes.data(), version1.data(), version1.size());
  try {
    FilmState::fromBytes(bytes);
    ADD_FAILURE() << "version-1 sums were read";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("older lensrt"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lensrt
