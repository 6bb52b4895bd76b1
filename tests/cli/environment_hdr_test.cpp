// `--env FILE.hdr`: a Radiance RGBE lat-long map lights the scene like an EXR,
// +Y up (the README's convention), and a broken one is one error line.
#include <gtest/gtest.h>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

using cli::kSkyOnlyGltf;

TEST(EnvironmentHdr, LatLongRgbeMapIsReadWithYUp) {
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", kSkyOnlyGltf);
  // A 16x8 flat (not run-length encoded) RGBE file: upper hemisphere (top
  // rows) radiance 3 = 0.75 * 2^2, lower 1 = 0.5 * 2^1, both exact.
  std::string hdr = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n";
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      hdr += y < 4 ? std::string{char(192), char(192), char(192), char(130)}
                   : std::string{char(128), char(128), char(128), char(129)};
  cli::writeFile(dir / "sky.hdr", hdr);
  const RunResult r =
      runLensrt({"render", (dir / "sky.gltf").string(), "--env", (dir / "sky.hdr").string(), "--res", "20x20",
                 "--spp", "16", "--spectral", "off", "-q", "-o", (dir / "out.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const Image img = readImage(dir / "out.exr");
  const int g = img.channelIndex("G");
  // Rows 2 and 17 are mirror images about the horizon: the same film falloff,
  // so their ratio is the sky's, 3.
  for (int x = 0; x < img.width; ++x) {
    const double up = img.at(x, 2, g), down = img.at(x, img.height - 3, g);
    ASSERT_GT(down, 0.1);
    EXPECT_NEAR(up / down, 3.0, 0.05) << x;
  }
}

TEST(EnvironmentHdr, TruncatedMapIsOneErrorLine) {
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", kSkyOnlyGltf);
  cli::writeFile(dir / "cut.hdr", "#?RADIANCE\n");
  const RunResult r = runLensrt({"render", (dir / "sky.gltf").string(), "--env", (dir / "cut.hdr").string(),
                                 "-q", "-o", (dir / "out.exr").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("lensrt: error: " + (dir / "cut.hdr").string() + ": ", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

}  // namespace
}  // namespace lensrt
