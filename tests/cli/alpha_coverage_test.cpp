// A is coverage: of the camera samples that reach the scene straight through
// the lens, the fraction that hit geometry. The lens's vignetting (samples
// it blocks) stays in RGB, and flare's samples, reflected in the lens, are
// ghosts of other directions over the image, not what it shows. Before,
// A was hits over all samples: 0.97 at the centre and 0.70 in a corner of
// the Cornell box at f/4, and 0.60 everywhere with --flare on.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const char* kWhite = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0}})";
// The camera at the origin looking down -Z (glTF's camera axis).
const char* kAtOrigin = R"("translation":[0,0,0])";

struct Render {
  Image image;
  ImageMetadata meta;
};

// Through dgauss-50mm at f/4 on the default 36 x 24 mm sensor, 24 x 16
// pixels: its corners lose many samples to the lens (vignetting).
const std::vector<std::string> kLens = {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "4"};

Render renderFile(const TempDir& dir, const std::string& scene, const std::vector<std::string>& camera,
                  const std::vector<std::string>& extra) {
  std::vector<std::string> args = {
      "render", scene, "--res", "24x16", "--spectral", "off", "-q", "-o", (dir / "out.exr").string()};
  args.insert(args.end(), camera.begin(), camera.end());
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  Render out;
  if (r.status == 0) out.image = readImage(dir / "out.exr", &out.meta);
  return out;
}

Render render(const TempDir& dir, const cli::QuadScene& scene, const std::vector<std::string>& extra,
              const std::vector<std::string>& camera = kLens) {
  cli::writeFile(dir / "scene.gltf", cli::quadsGltf(scene));
  return renderFile(dir, (dir / "scene.gltf").string(), camera, extra);
}

double blockedShare(const Render& r) {
  const double spp = std::stod(r.meta.at("lensrt:spp"));
  return std::stod(r.meta.at("lensrt:blocked_camera_rays")) / (spp * r.image.width * r.image.height);
}

// Every pixel's A is 1, exactly.
void expectOpaque(const Render& r) {
  const int a = r.image.channelIndex("A");
  int notOne = 0;
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) notOne += r.image.at(x, y, a) != 1.0f;
  EXPECT_EQ(notOne, 0) << "corner A " << r.image.at(0, 0, a) << ", centre A "
                       << r.image.at(r.image.width / 2, r.image.height / 2, a);
}

// A closed 2 m box around the camera, lit inside: every sample that leaves
// the lens hits a wall, so A is 1 in every pixel, exactly (a ratio of equal
// counts), with the lens blocking samples and with flare's reflections.
// 64 spp: with flare on, 64% of the samples are blocked, and a pixel all of
// whose samples are (A 0: nothing reached the scene) has odds 0.64^64.
TEST(AlphaCoverage, AClosedBoxIsOpaqueEverywhereWithAndWithoutFlare) {
  const TempDir dir;
  cli::QuadScene box;
  // Six walls facing in.
  box.quads = {{{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}}, 0},
               {{{-1, -1, 1}, {-1, 1, 1}, {1, 1, 1}, {1, -1, 1}}, 0},
               {{{-1, -1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}}, 0},
               {{{-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}}, 0},
               {{{-1, -1, -1}, {-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}}, 0},
               {{{1, -1, -1}, {1, -1, 1}, {1, 1, 1}, {1, 1, -1}}, 0}};
  box.materials = kWhite;
  box.light = R"({"type":"point","intensity":200})";
  box.lightPlacement = R"("translation":[0,0.6,-0.3])";
  box.cameraPlacement = kAtOrigin;
  for (const char* flare : {"off", "on"}) {
    SCOPED_TRACE(std::string("--flare ") + flare);
    const Render r = render(dir, box, {"--spp", "64", "--focus", "1", "--flare", flare});
    ASSERT_GT(r.image.width, 0);
    // The lens does block samples (else the test could not fail).
    EXPECT_GT(blockedShare(r), 0.02);
    expectOpaque(r);
  }
}

// A wall filling the left half of the view, in focus 2 m away, before the
// sky: its edge (x = 0, on the axis) images onto the frame's centre line, so
// the left 12 columns see the wall alone (A 1, the vignetted corners too) and
// the right 12 the sky alone (A 0); the mean is 0.5 but for the lens's blur
// across the two centre columns. With flare on too: its reflections of the
// sky over the wall are light, not holes in it.
TEST(AlphaCoverage, AHalfBackgroundSceneIsHalfCovered) {
  const TempDir dir;
  cli::QuadScene half;
  half.quads = {{{{-50, -50, -2}, {0, -50, -2}, {0, 50, -2}, {-50, 50, -2}}, 0}};
  half.materials = kWhite;
  half.cameraPlacement = kAtOrigin;
  for (const char* flare : {"off", "on"}) {
    SCOPED_TRACE(std::string("--flare ") + flare);
    const Render r =
        render(dir, half, {"--spp", "64", "--focus", "2", "--env", "constant:1", "--flare", flare});
    ASSERT_EQ(r.image.width, 24);
    EXPECT_GT(blockedShare(r), 0.02);
    const int a = r.image.channelIndex("A");
    double sum = 0;
    int wrong = 0;
    for (int y = 0; y < r.image.height; ++y)
      for (int x = 0; x < r.image.width; ++x) {
        const float alpha = r.image.at(x, y, a);
        sum += alpha;
        wrong += (x < 11 && alpha != 1.0f) || (x > 12 && alpha != 0.0f);
      }
    EXPECT_EQ(wrong, 0) << "corner A " << r.image.at(0, 0, a);
    EXPECT_NEAR(sum / (r.image.width * r.image.height), 0.5, 1.0 / r.image.width);
  }
}

// The Cornell box (scenes/cornell.gltf), its camera 1.44 m before the open
// front: on a 33 x 22 mm sensor the frame stays inside the box (the full
// frame's 36 mm sees past the side walls' front edges, where A rightly
// falls), so every sample that leaves the lens hits and A is 1 to the
// corners. 32 spp: with flare on, 64% of the samples are blocked, and a
// pixel all of whose samples are (A 0) has odds 0.64^32 = 6e-7.
TEST(AlphaCoverage, TheCornellBoxThroughALensIsOpaqueToItsCorners) {
  const TempDir dir;
  const std::string cornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";
  for (const char* flare : {"off", "on"}) {
    SCOPED_TRACE(std::string("--flare ") + flare);
    const Render r = renderFile(dir, cornell, kLens, {"--sensor", "33x22", "--spp", "32", "--flare", flare});
    ASSERT_EQ(r.image.width, 24);
    EXPECT_GT(blockedShare(r), 0.02);
    expectOpaque(r);
  }
}

// An object's edge is partly covered. The wall of the half scene ends at
// x = 3 cm, half a pixel right of the axis (a pixel spans 6.4 cm at 2 m
// through the pinhole's 0.5 rad, 5.8 cm through the lens): column 12 sees
// the edge across its middle, A strictly between 0 and 1 (about 0.5), and
// the sky alone beyond is 0. Through the pinhole, which blocks nothing and
// reflects nothing, A is what it always was: hits over samples, a multiple
// of 1/spp.
TEST(AlphaCoverage, AnEdgeIsPartlyCoveredAndTheSkyIsZero) {
  const TempDir dir;
  cli::QuadScene edge;
  edge.quads = {{{{-50, -50, -2}, {0.03f, -50, -2}, {0.03f, 50, -2}, {-50, 50, -2}}, 0}};
  edge.materials = kWhite;
  edge.cameraPlacement = kAtOrigin;
  const std::vector<std::string> pinhole = {"--camera", "pinhole"};
  struct Case {
    const char* name;
    std::vector<std::string> camera;
    const char* flare;
  };
  for (const Case& c :
       {Case{"pinhole", pinhole, "off"}, Case{"lens", kLens, "off"}, Case{"lens", kLens, "on"}}) {
    SCOPED_TRACE(std::string(c.name) + " --flare " + c.flare);
    const int spp = 64;
    const Render r = render(
        dir, edge, {"--spp", std::to_string(spp), "--focus", "2", "--env", "constant:1", "--flare", c.flare},
        c.camera);
    ASSERT_EQ(r.image.width, 24);
    const int a = r.image.channelIndex("A");
    int wrong = 0, partial = 0;
    for (int y = 0; y < r.image.height; ++y)
      for (int x = 0; x < r.image.width; ++x) {
        const float alpha = r.image.at(x, y, a);
        wrong += (x < 11 && alpha != 1.0f) || (x > 13 && alpha != 0.0f);
        if (x == 12) {
          partial += alpha > 0.2f && alpha < 0.8f;
          if (c.camera == pinhole) {
            EXPECT_EQ(alpha * spp, std::round(alpha * spp)) << "row " << y;
          }
        }
      }
    EXPECT_EQ(wrong, 0) << "corner A " << r.image.at(0, 0, a);
    EXPECT_EQ(partial, r.image.height) << "A at the edge " << r.image.at(12, 8, a);
  }
}

}  // namespace
}  // namespace lensrt
