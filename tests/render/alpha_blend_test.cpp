// alphaMode BLEND as stochastic transparency, through the whole renderer: a
// surface of alpha a in front of an emitter lets 1 - a of its light through.
#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_camera.h"
#include "render/test_scene_util.h"

namespace lensrt {
namespace {

// A uniform emitter of radiance 1 filling the view, seen from above through
// (optionally) a black BLEND sheet of the given alpha.
SceneDesc emitterBehindSheet(bool sheet, float alpha) {
  SceneDesc s;
  s.sourceFile = "blend (in code)";
  s.meshes.push_back(test::makeQuadY(0, 40));
  s.meshes[0].material = 0;
  s.instances.push_back({0, Transform()});
  s.materials.push_back(test::whiteMatte());
  s.materials[0].baseColor = {0, 0, 0, 1};
  s.materials[0].emissive = {1, 1, 1};
  if (sheet) {
    s.meshes.push_back(test::makeQuadY(1, 40));
    s.meshes[1].material = 1;
    s.instances.push_back({1, Transform()});
    Material black = test::whiteMatte(true);
    black.baseColor = {0, 0, 0, alpha};
    black.alphaMode = AlphaMode::Blend;
    s.materials.push_back(black);
  }
  return s;
}

TEST(AlphaBlend, SheetOfAlphaAQuarterTransmitsThreeQuarters) {
  const PinholeCamera camera(Transform::lookAt({0, 3, 0}, {0, 0, 0}, {0, 0, -1}), {24, 24, 36, 36}, 0.5);
  test::TestRenderSetup setup;  // black environment: only the emitter lights anything
  setup.render.samplesPerPixel = 16;
  setup.render.threads = 2;
  const Image openImage = test::renderTestScene(emitterBehindSheet(false, 1), camera, setup);
  const Image behindImage = test::renderTestScene(emitterBehindSheet(true, 0.25f), camera, setup);
  const double open = test::channelMean(openImage, "G"), behind = test::channelMean(behindImage, "G");
  ASSERT_GT(open, 0.1);
  // 9216 camera paths, each through with probability 0.75: sigma 0.0045.
  EXPECT_NEAR(behind / open, 0.75, 0.02);
  // Each of a pixel's 16 paths decides on its own: the per-pixel ratio is a
  // binomial fraction with sigma sqrt(0.75 * 0.25 / 16) = 0.108 (0.433 if a
  // pixel's paths all decided alike).
  const int g = openImage.channelIndex("G");
  double sum = 0, sum2 = 0;
  const int n = openImage.width * openImage.height;
  for (int y = 0; y < openImage.height; ++y)
    for (int x = 0; x < openImage.width; ++x) {
      const double r = behindImage.at(x, y, g) / openImage.at(x, y, g);
      sum += r;
      sum2 += r * r;
    }
  const double sigma = std::sqrt(sum2 / n - (sum / n) * (sum / n));
  EXPECT_NEAR(sigma, 0.108, 0.015);
  const double opaque =
      test::channelMean(test::renderTestScene(emitterBehindSheet(true, 1), camera, setup), "G");
  EXPECT_EQ(opaque, 0.0);  // alpha 1 blocks every path (a black sheet reflects nothing)
}

// A white floor lit only by an emitter overhead (out of view) of the given
// alpha mode and alpha: next-event estimation and BSDF sampling must both see
// the emitter's coverage.
SceneDesc floorUnderEmitter(AlphaMode mode, float alpha) {
  SceneDesc s;
  s.sourceFile = "blended emitter (in code)";
  s.meshes.push_back(test::makeQuadY(0, 40));
  s.meshes.push_back(test::makeRectFacingDown(1, 3, -1, 1, 2));
  s.meshes[0].material = 0;
  s.meshes[1].material = 1;
  s.instances = {{0, Transform()}, {1, Transform()}};
  s.materials = {test::whiteMatte(), test::whiteMatte()};
  s.materials[1].baseColor = {0, 0, 0, alpha};
  s.materials[1].emissive = {4, 4, 4};
  s.materials[1].alphaMode = mode;
  return s;
}

TEST(AlphaBlend, BlendedEmitterShinesWithItsCoverage) {
  const PinholeCamera camera(Transform::lookAt({-1, 1, 0}, {-1, 0, 0}, {0, 0, -1}), {16, 16, 36, 36}, 0.4);
  test::TestRenderSetup setup;
  setup.render.samplesPerPixel = 64;
  setup.render.threads = 2;
  const double full =
      test::channelMean(test::renderTestScene(floorUnderEmitter(AlphaMode::Opaque, 1), camera, setup), "G");
  ASSERT_GT(full, 0.05);
  const double quarter = test::channelMean(
      test::renderTestScene(floorUnderEmitter(AlphaMode::Blend, 0.25f), camera, setup), "G");
  EXPECT_NEAR(quarter / full, 0.25, 0.02);
  // MASK below the cutoff: no emitter at all, by light sampling either.
  const double masked =
      test::channelMean(test::renderTestScene(floorUnderEmitter(AlphaMode::Mask, 0.25f), camera, setup), "G");
  EXPECT_EQ(masked, 0.0);
}

}  // namespace
}  // namespace lensrt
