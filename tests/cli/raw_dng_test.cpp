// lensrt render --raw OUT.dng: the raw file developers read (dcraw decodes
// nothing under 22 x 22, hence 33 x 23: odd, so the pattern wraps). Debian's own
// raw developers check it: dcraw and LibRaw's raw-identify identify the
// camera, size and pattern; `dcraw -D -4 -T` returns exactly the mosaic lensrt
// wrote; a grey card developed with `dcraw -w -o 1 -4 -T` comes out neutral.
#include <gtest/gtest.h>
#include <tiffio.h>

#include <cmath>
#include <filesystem>
#include <memory>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::runProgram;
using cli::RunResult;
using cli::TempDir;

const std::string kScene = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";

bool haveDevelopers() {
  return runProgram("sh", {"-c", "command -v dcraw && command -v raw-identify"}).status == 0;
}

struct Tiff {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint16_t> values;  // row-major, interleaved
  std::uint16_t at(int x, int y, int c = 0) const {
    return values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) +
                  std::size_t(c)];
  }
};

// A 16-bit TIFF as dcraw writes it (one strip per row or more, contiguous).
Tiff readTiff(const std::filesystem::path& file) {
  struct Closer {
    void operator()(TIFF* t) const { TIFFClose(t); }
  };
  const std::unique_ptr<TIFF, Closer> tiff(TIFFOpen(file.c_str(), "r"));
  EXPECT_TRUE(tiff) << file;
  Tiff out;
  if (!tiff) return out;
  std::uint32_t w = 0, h = 0;
  std::uint16_t spp = 1, bits = 0;
  TIFFGetField(tiff.get(), TIFFTAG_IMAGEWIDTH, &w);
  TIFFGetField(tiff.get(), TIFFTAG_IMAGELENGTH, &h);
  TIFFGetFieldDefaulted(tiff.get(), TIFFTAG_SAMPLESPERPIXEL, &spp);
  TIFFGetField(tiff.get(), TIFFTAG_BITSPERSAMPLE, &bits);
  EXPECT_EQ(bits, 16);
  out.width = int(w), out.height = int(h), out.channels = spp;
  out.values.resize(std::size_t(w) * h * spp);
  for (std::uint32_t y = 0; y < h; ++y)
    TIFFReadScanline(tiff.get(), &out.values[std::size_t(y) * w * spp], y, 0);
  return out;
}

RunResult render(const TempDir& dir, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render",
                                   kScene,
                                   "--res",
                                   "33x23",
                                   "--spp",
                                   "2",
                                   "-q",
                                   "-o",
                                   (dir / "a.exr").string(),
                                   "--raw",
                                   (dir / "a.dng").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return runLensrt(args);
}

TEST(RawDng, DcrawAndLibRawIdentifyTheCamera) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw or raw-identify not installed (tools/setup installs them)";
  const TempDir dir;
  ASSERT_EQ(render(dir, {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "4", "--exposure",
                         "physical", "--shutter", "1/250", "--iso", "400"})
                .status,
            0);
  const RunResult d = runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()});
  ASSERT_EQ(d.status, 0) << d.err;
  for (const char* line :
       {"Camera: lensrt lens dgauss-50mm", "ISO speed: 400", "Shutter: 1/250.0 sec", "Aperture: f/4.0",
        "Image size:    33 x 23", "Filter pattern: RG/GB", "DNG Version: 1.4"})
    EXPECT_NE(d.out.find(line), std::string::npos) << line << "\n" << d.out;
  const RunResult l = runProgram("raw-identify", {"-v", (dir / "a.dng").string()});
  ASSERT_EQ(l.status, 0) << l.err;
  for (const char* line : {"Camera: lensrt lens dgauss-50mm", "ISO speed: 400", "Image size:    33 x 23",
                           "Filter pattern: RGGBRGGB"})
    EXPECT_NE(l.out.find(line), std::string::npos) << line << "\n" << l.out;
  ASSERT_EQ(render(dir, {"--cfa", "GBRG"}).status, 0);
  EXPECT_NE(runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()}).out.find("Filter pattern: GB/RG"),
            std::string::npos);
}

// Each site holds its colour's value of the EXR: v * 65535 (noiseless), or
// with --noise on the DN the EXR's reading of that colour came from.
void expectMosaicOf(const TempDir& dir, const std::string& pattern, bool noise) {
  const RunResult d = runProgram("dcraw", {"-D", "-4", "-T", (dir / "a.dng").string()});
  ASSERT_EQ(d.status, 0) << d.err;
  const Tiff raw = readTiff(dir / "a.tiff");
  ImageMetadata meta;
  const Image img = readImage(dir / "a.exr", &meta);
  ASSERT_EQ(raw.width, img.width);
  ASSERT_EQ(raw.height, img.height);
  const double perValue = noise ? std::stod(meta["lensrt:sensor_electrons_per_value"]) *
                                      std::stod(meta["lensrt:sensor_dn_per_electron"])
                                : 65535.0;
  const double black = noise ? 64.0 : 0.0;  // the default sensor's black level
  int mismatches = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const char colour = pattern[std::size_t((y & 1) * 2 + (x & 1))];
      const double v = img.at(x, y, img.channelIndex(std::string(1, colour)));
      const double expected =
          noise ? std::round(black + v * perValue) : std::round(std::clamp(v, 0.0, 1.0) * 65535);
      mismatches += raw.at(x, y) != std::uint16_t(expected);
    }
  EXPECT_EQ(mismatches, 0);
}

TEST(RawDng, DcrawReturnsTheMosaicLensrtWrote) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  ASSERT_EQ(render(dir, {"--cfa", "GRBG"}).status, 0);
  expectMosaicOf(dir, "GRBG", false);
  ASSERT_EQ(render(dir, {"--noise", "on"}).status, 0);
  expectMosaicOf(dir, "RGGB", true);
}

// A crop starting on an odd row and column: the file declares the pattern as
// seen from its first pixel (the frame's RGGB is BGGR... from (1, 1)).
TEST(RawDng, ACropDeclaresItsOwnPhaseOfThePattern) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  ASSERT_EQ(render(dir, {"--crop", "1,30,1,23"}).status, 0);
  const RunResult d = runProgram("dcraw", {"-i", "-v", (dir / "a.dng").string()});
  EXPECT_NE(d.out.find("Filter pattern: BG/GR"), std::string::npos) << d.out;
  expectMosaicOf(dir, "BGGR", false);
}

TEST(RawDng, AGreyCardDevelopsNeutral) {
  if (!haveDevelopers()) GTEST_SKIP() << "dcraw not installed (tools/setup installs it)";
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  const RunResult r = runLensrt({"render", (dir / "sky.gltf").string(), "--env", "constant:0.18", "--film",
                                 "radiance", "--res", "32x24", "--spp", "4", "-q", "-o",
                                 (dir / "a.exr").string(), "--raw", (dir / "a.dng").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const RunResult d = runProgram("dcraw", {"-w", "-o", "1", "-4", "-T", (dir / "a.dng").string()});
  ASSERT_EQ(d.status, 0) << d.err;
  const Tiff rgb = readTiff(dir / "a.tiff");
  ASSERT_EQ(rgb.channels, 3);
  double sum[3] = {0, 0, 0};
  for (int y = 4; y < rgb.height - 4; ++y)
    for (int x = 4; x < rgb.width - 4; ++x)
      for (int c = 0; c < 3; ++c) sum[c] += rgb.at(x, y, c);
  const double mean = (sum[0] + sum[1] + sum[2]) / 3;
  ASSERT_GT(mean, 0);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c] / mean, 1.0, 0.02) << "channel " << c;
}

}  // namespace
}  // namespace lensrt
