// The white furnace at `lensrt render`'s default settings: scenes/furnace.gltf
// (a white Lambertian sphere, no light) renders under the default environment
// (a uniform sky of radiance 1) through the default pinhole, whose film
// records radiance. Every pixel, sphere and sky alike, must then read 1 within
// its noise, at any resolution and field of view: no cos^4 fall-off, no
// exposure scale, no energy gained or lost at the sphere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kFurnace = std::string(LENSRT_SOURCE_DIR) + "/scenes/furnace.gltf";

struct FurnaceStats {
  double worstZ = 0;      // largest |value - 1| / (its standard error + a floor), over pixels and channels
  double mean = 0;        // mean R over the image
  double cornerMean = 0;  // mean R of the four corner pixels
  int spherePixels = 0;   // pixels fully covered by the sphere
};

FurnaceStats renderFurnace(const TempDir& dir, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"render", kFurnace, "--spp", "16", "--seed", "3", "--aov", "variance"};
  args.insert(args.end(), extra.begin(), extra.end());
  const std::string out = (dir / "f.exr").string();
  args.insert(args.end(), {"-o", out});
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  // The one-line notice that the default environment lights the scene.
  EXPECT_NE(r.err.find("default environment, a uniform sky of radiance 1"), std::string::npos) << r.err;
  ImageMetadata meta;
  const Image img = readImage(out, &meta);
  EXPECT_EQ(meta["lensrt:film"], "radiance");
  EXPECT_EQ(meta["lensrt:environment"].rfind("default constant", 0), 0u) << meta["lensrt:environment"];
  FurnaceStats s;
  const int a = img.channelIndex("A");
  const char* names[3][2] = {{"R", "variance.R"}, {"G", "variance.G"}, {"B", "variance.B"}};
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      for (const auto& [c, v] : names) {
        const double value = img.at(x, y, img.channelIndex(c));
        const double sigma = std::sqrt(img.at(x, y, img.channelIndex(v)));
        // The floor covers pixels whose few samples happened to agree (and
        // the float rounding of the sky's exact 1).
        s.worstZ = std::max(s.worstZ, std::abs(value - 1.0) / (sigma + 2e-3));
      }
      s.mean += img.at(x, y, img.channelIndex("R"));
      if (img.at(x, y, a) == 1.0f) ++s.spherePixels;
    }
  s.mean /= double(img.width) * img.height;
  for (const auto& [x, y] :
       {std::pair{0, 0}, {img.width - 1, 0}, {0, img.height - 1}, {img.width - 1, img.height - 1}})
    s.cornerMean += img.at(x, y, img.channelIndex("R")) / 4;
  return s;
}

TEST(FurnaceCli, EveryPixelRendersOneAtTheDefaultSettings) {
  const TempDir dir;
  // Resolutions and fields of view (the file's 37.8 degrees, then 90 and 120
  // degrees on the 24 mm-high square sensor: 12 and 6.93 mm lenses).
  const std::vector<std::vector<std::string>> cases{
      {"--res", "24x24"},
      {"--res", "40x20"},
      {"--res", "16x32", "--focal-length", "12"},
      {"--res", "32x32", "--focal-length", "6.93"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c[1] + (c.size() > 2 ? " f=" + c[3] : ""));
    const FurnaceStats s = renderFurnace(dir, c);
    EXPECT_GT(s.spherePixels, 8) << "the sphere is in view";
    EXPECT_LT(s.worstZ, 5.0) << "some pixel differs from 1 by more than 5 standard errors";
    EXPECT_NEAR(s.mean, 1.0, 5e-3);
    // The sky in the corners: spectral transport's colour noise (3% per
    // pixel at 16 spp, so about 1.7% on the four) is all there is; cos^4
    // would take 34% or more.
    EXPECT_NEAR(s.cornerMean, 1.0, 0.1);
    // RGB transport carries the sky's 1 exactly.
    std::vector<std::string> rgb = c;
    rgb.insert(rgb.end(), {"--spectral", "off"});
    EXPECT_NEAR(renderFurnace(dir, rgb).cornerMean, 1.0, 1e-6);
  }
}

// The same scene on the physical film (--film irradiance) is what the test
// above rules out: cos^4 of the field angle darkens the corners (to about
// 0.02 at a 120 degree field: the corner ray is 78 degrees off the axis).
TEST(FurnaceCli, TheIrradianceFilmDarkensTheCorners) {
  const TempDir dir;
  const std::string out = (dir / "i.exr").string();
  const RunResult r = runLensrt({"render", kFurnace, "--res", "32x32", "--focal-length", "6.93", "--spp",
                                 "64", "--film", "irradiance", "-q", "-o", out});
  ASSERT_EQ(r.status, 0) << r.err;
  ImageMetadata meta;
  const Image img = readImage(out, &meta);
  EXPECT_EQ(meta["lensrt:film"], "irradiance");
  // cos^4 averaged over the corner pixel, whose tangents run from t (1 - 1/16) to t on both axes.
  const double t = 12.0 / 6.93;
  double expected = 0;
  constexpr int kSub = 32;
  for (int i = 0; i < kSub; ++i)
    for (int j = 0; j < kSub; ++j) {
      const double tx = t * (1.0 - 2.0 * (i + 0.5) / kSub / 32), ty = t * (1.0 - 2.0 * (j + 0.5) / kSub / 32);
      const double cos2 = 1.0 / (1.0 + tx * tx + ty * ty);
      expected += cos2 * cos2 / (kSub * kSub);
    }
  EXPECT_NEAR(img.at(0, 0, img.channelIndex("R")), expected, 0.05 * expected);
  EXPECT_LT(expected, 0.03);
}

}  // namespace
}  // namespace lensrt
