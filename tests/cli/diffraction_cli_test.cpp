// --diffraction on in renders: a small bright lamp of scenes/dof_row.gltf
// (30 m away, in the black sky band) through a thin lens at f/22 with six
// blades, in a 160 x 160 crop of a 6400 x 3600 frame (5.6 um pixels, the
// Airy disc's first dark ring 2.7 px out). Diffraction moves the lamp's light
// into its starburst and takes none: the crop's sum stays within 0.5% (the
// far field's table reaches 70 px from the lamp, inside the crop), and
// about 5% of it falls outside the lamp's sharp disc. The bits do not depend on the thread count or tiles.
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

Image renderLamp(const TempDir& dir, const std::string& name, const std::vector<std::string>& extra) {
  std::vector<std::string> args{"render",
                                std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf",
                                "--camera",
                                "thin",
                                "--focal-length",
                                "50",
                                "--fstop",
                                "22",
                                "--blades",
                                "6",
                                "--focus",
                                "inf",
                                "--res",
                                "6400x3600",
                                "--crop",
                                "2225,2385,45,205",
                                "--spp",
                                "32",
                                "-q",
                                "-o",
                                (dir / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return readImage(dir / name);
}

double sumOf(const Image& image) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) sum += image.at(x, y, c);
  return sum;
}

// The part of `image`'s light in the pixels where `geometric` has none (the
// black sky around the lamp's sharp disc).
double outsideShare(const Image& image, const Image& geometric) {
  double outside = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (geometric.at(x, y, 0) + geometric.at(x, y, 1) + geometric.at(x, y, 2) == 0.0f)
        for (int c = 0; c < 3; ++c) outside += image.at(x, y, c);
  return outside / sumOf(image);
}

TEST(DiffractionCli, TheStarburstKeepsTheLampsLight) {
  const TempDir dir;
  const Image off = renderLamp(dir, "off.exr", {});
  const Image on = renderLamp(dir, "on.exr", {"--diffraction", "on"});
  ASSERT_GT(off.width, 0);
  ASSERT_GT(on.width, 0);
  const double sumOff = sumOf(off), sumOn = sumOf(on);
  ASSERT_GT(sumOff, 0.0);
  EXPECT_NEAR(sumOn / sumOff, 1.0, 0.005);
  // About 5% of the light lands outside the disc (measured 4.97% at 64 spp).
  EXPECT_GT(outsideShare(on, off), 0.03);
}

TEST(DiffractionCli, TheSameBitsOnAnyThreadsAndTiles) {
  const TempDir dir;
  const Image one = renderLamp(dir, "one.exr", {"--diffraction", "on", "--threads", "1"});
  const Image two = renderLamp(dir, "two.exr", {"--diffraction", "on", "--threads", "2", "--tile-size", "8"});
  ASSERT_GT(one.width, 0);
  EXPECT_EQ(one.pixels, two.pixels);
}

// RGB transport diffracts too (each sample at its own wavelength, weighted
// into RGB); the pinhole has no aperture and says so.
TEST(DiffractionCli, RgbTransportDiffractsAndThePinholeRefuses) {
  const TempDir dir;
  const Image off = renderLamp(dir, "off.exr", {"--spectral", "off"});
  const Image on = renderLamp(dir, "on.exr", {"--spectral", "off", "--diffraction", "on"});
  ASSERT_GT(on.width, 0);
  EXPECT_NEAR(sumOf(on) / sumOf(off), 1.0, 0.005);
  EXPECT_GT(outsideShare(on, off), 0.03);
  const RunResult pinhole =
      runLensrt({"render", std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf", "--diffraction", "on",
                 "--res", "16x9", "-o", (dir / "p.exr").string()});
  EXPECT_EQ(pinhole.status, 2);
  EXPECT_NE(pinhole.err.find("--diffraction: the pinhole has no aperture"), std::string::npos) << pinhole.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "p.exr"));
}

}  // namespace
}  // namespace lensrt
