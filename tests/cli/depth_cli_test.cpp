// Depth as a user measures it: from the camera node's origin (the glTF
// camera's position; for the lens models the entrance pupil, where camera
// space starts), whatever the model. A wall 2 m ahead of the node reads
// depth.Z = 2 at the frame's centre and Z (along the viewing axis) = 2 in
// every pixel, through the pinhole, the thin lens, the thick lens and the
// full lens (dgauss-50mm, wide-22mm), whose rays leave from the front glass
// 12-20 mm ahead of the node (before, depth.Z read 1.980 through dgauss-50mm
// and 1.988 through wide-22mm). Off the centre, depth.Z is the distance to
// the point seen, 2 / cos of the ray's angle: through the pinhole at the
// corner pixel that is 2 sqrt(1 + tan^2 x + tan^2 y).
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

constexpr int kWidth = 33, kHeight = 21;

Image renderWall(const TempDir& dir, const std::vector<std::string>& camera) {
  cli::QuadScene wall;
  wall.quads = {{{{-50, -50, -2}, {50, -50, -2}, {50, 50, -2}, {-50, 50, -2}}, 0}};
  wall.materials = R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.8,0.8,1],"metallicFactor":0}})";
  wall.cameraPlacement = R"("translation":[0,0,0])";
  cli::writeFile(dir / "wall.gltf", cli::quadsGltf(wall));
  std::vector<std::string> args = {"render",
                                   (dir / "wall.gltf").string(),
                                   "--res",
                                   std::to_string(kWidth) + "x" + std::to_string(kHeight),
                                   "--env",
                                   "constant:1",
                                   "--aov",
                                   "depth,z",
                                   "-q",
                                   "-o",
                                   (dir / "out.exr").string()};
  args.insert(args.end(), camera.begin(), camera.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? readImage(dir / "out.exr") : Image();
}

TEST(DepthCli, AWallTwoMetresAheadReadsTwoThroughEveryModel) {
  const TempDir dir;
  const std::vector<std::vector<std::string>> cameras = {
      {"--camera", "pinhole"},
      {"--camera", "thin", "--focal-length", "50", "--fstop", "8", "--focus", "2"},
      {"--camera", "thick", "--lens", "dgauss-50mm", "--fstop", "8", "--focus", "2"},
      {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "8", "--focus", "2"},
      {"--camera", "lens", "--lens", "wide-22mm", "--fstop", "8", "--focus", "2"}};
  for (const std::vector<std::string>& camera : cameras) {
    SCOPED_TRACE(camera[1] + (camera.size() > 3 ? " " + camera[3] : std::string()));
    std::vector<std::string> args = camera;
    args.insert(args.end(), {"--spp", "4"});
    const Image image = renderWall(dir, args);
    ASSERT_EQ(image.width, kWidth);
    const int depth = image.channelIndex("depth.Z"), z = image.channelIndex("Z"), a = image.channelIndex("A");
    ASSERT_GE(depth, 0);
    ASSERT_GE(z, 0);
    EXPECT_NEAR(image.at(kWidth / 2, kHeight / 2, depth), 2.0f, 2e-3f);
    int wrong = 0, seen = 0;
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        if (image.at(x, y, a) == 0.0f) continue;  // a corner the lens vignettes away entirely
        ++seen;
        const float planar = image.at(x, y, z), distance = image.at(x, y, depth);
        wrong += std::abs(planar - 2.0f) > 1e-3f || distance < planar - 1e-4f;
      }
    EXPECT_GT(seen, kWidth * kHeight / 2);
    EXPECT_EQ(wrong, 0) << "corner Z " << image.at(0, 0, z) << ", depth " << image.at(0, 0, depth);
  }
}

TEST(DepthCli, ThePinholesCornerReadsTheDistanceAlongItsRay) {
  const TempDir dir;
  const Image image = renderWall(dir, {"--camera", "pinhole", "--spp", "64"});
  ASSERT_EQ(image.width, kWidth);
  // The glTF camera's yfov is 0.5 rad; the pixel's centre is half a pixel in.
  const double tanY = std::tan(0.25), tanX = tanY * kWidth / kHeight;
  const double u = (kWidth - 1.0) / kWidth, v = (kHeight - 1.0) / kHeight;  // the corner pixel's centre
  const double expected = 2.0 * std::sqrt(1.0 + std::pow(u * tanX, 2) + std::pow(v * tanY, 2));
  // Over the pixel the distance varies by about 1%: its mean is near the centre's value.
  EXPECT_NEAR(image.at(0, 0, image.channelIndex("depth.Z")), expected, 0.01);
}

}  // namespace
}  // namespace lensrt
