// A glTF file with a camera and no meshes renders the environment: a uniform
// sky seen through the camera is the classic flat-field test of vignetting.
#include <gtest/gtest.h>

#include <cmath>

#include "cli/cli_util.h"
#include "core/constants.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

using cli::kSkyOnlyGltf;

Image render(const TempDir& dir, const std::vector<std::string>& extra, const std::string& name) {
  std::vector<std::string> args = {"render", (dir / "sky.gltf").string(), "--env", "constant:1", "--res",
                                   "30x20", "--spp", "64",
                                   // RGB transport: the sky's 1 without spectral transport's colour noise.
                                   "--spectral", "off", "-o", (dir / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("the scene has no meshes: rendering the environment only"), std::string::npos)
      << r.err;
  return readImage(dir / name);
}

// Mean of channel G over the 3x3 pixels at each corner, and over the 4x4 in the middle.
double corners(const Image& img) {
  const int g = img.channelIndex("G");
  double sum = 0;
  for (const int x0 : {0, img.width - 3})
    for (const int y0 : {0, img.height - 3})
      for (int y = y0; y < y0 + 3; ++y)
        for (int x = x0; x < x0 + 3; ++x) sum += img.at(x, y, g);
  return sum / 36;
}
double centre(const Image& img) {
  const int g = img.channelIndex("G");
  double sum = 0;
  for (int y = img.height / 2 - 2; y < img.height / 2 + 2; ++y)
    for (int x = img.width / 2 - 2; x < img.width / 2 + 2; ++x) sum += img.at(x, y, g);
  return sum / 16;
}

TEST(FlatField, PinholeSeesTheSkyAsItsFilmPrescribes) {
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", kSkyOnlyGltf);
  // With radiance film (once it exists) the pinhole records the sky's radiance
  // everywhere; physical (irradiance) film records L cos^4(theta).
  const bool radianceFilm = runLensrt({"render", "--help"}).out.find("--film") != std::string::npos;
  const Image img =
      render(dir, radianceFilm ? std::vector<std::string>{"--film", "radiance"} : std::vector<std::string>{},
             "pinhole.exr");
  const int g = img.channelIndex("G");
  const double t = std::tan(0.35);  // half the yfov
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double tx = (2.0 * (x + 0.5) / img.width - 1.0) * t * img.width / img.height,
                   ty = (2.0 * (y + 0.5) / img.height - 1.0) * t;
      const double cos2 = 1.0 / (1.0 + tx * tx + ty * ty);
      const double expected = radianceFilm ? 1.0 : cos2 * cos2;
      EXPECT_NEAR(img.at(x, y, g), expected, 0.01 * expected) << x << "," << y;
    }
}

TEST(FlatField, LensVignettesWideOpenLessStoppedDown) {
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", kSkyOnlyGltf);
  const Image open = render(dir, {"--camera", "lens", "--lens", "dgauss-50mm"}, "open.exr");
  const Image stopped = render(dir, {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "8"}, "f8.exr");
  // Normalized exposure: the axis records the sky's radiance at any f-number.
  EXPECT_NEAR(centre(open), 1.0, 0.03);
  EXPECT_NEAR(centre(stopped), 1.0, 0.03);
  // Wide open the rim of the front and rear elements clips the oblique
  // bundles (mechanical vignetting, 0.22 of the centre measured); stopped
  // down the stop alone limits them and the corners keep most (0.80).
  EXPECT_LT(corners(open), 0.4 * centre(open));
  EXPECT_GT(corners(stopped), 0.6 * centre(stopped));
}

}  // namespace
}  // namespace lensrt
