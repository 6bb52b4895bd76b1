// The formats lensrt writes and reads through its OpenImageIO plugin: the
// codes each output stores (16-bit sRGB TIFF and JPEG 2000, 8-bit sRGB WebP,
// 10-bit Cineon log DPX), reading them back as stored values and as linear
// light, recognising them by content, and refusing sizes their headers
// declare before the decoder allocates them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "image/plugin_image_formats.h"
#include "image/cineon.h"
#include "image/image_io.h"
#include "image/srgb.h"
#include "image_test_util.h"
#include "oiio_plugin_for_tests.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

// Three rows of grey: 0.05, 0.25 and 4 (over white: TIFF clips it, DPX keeps it).
Image greyRows() {
  Image image(40, 33, {"R", "G", "B", "A"});
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float v = y < 11 ? 0.05f : y < 22 ? 0.25f : 4.0f;
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = v;
      image.at(x, y, 3) = 1;
    }
  return image;
}

struct FormatCase {
  const char* file;
  double full;             // the largest code
  double tolerance;        // of a stored value, in codes
  bool log;                // Cineon codes, else the sRGB curve clamped to [0,1]
  double linearTolerance;  // relative, of readLinearImage's values
};

const FormatCase kFormats[] = {{"a.tif", 65535, 0.5, false, 1e-4},
                               {"a.jp2", 65535, 0.5, false, 1e-4},
                               {"a.webp", 255, 1.5, false, 0.02},
                               {"a.dpx", 1023, 0.5, true, 0.005}};

TEST(PluginImageIo, EachFormatStoresItsCodesAndReadsBackAsLinearLight) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const ScratchDir dir;
  const Image image = greyRows();
  for (const FormatCase& f : kFormats) {
    SCOPED_TRACE(f.file);
    writeImage(dir / f.file, image, {{"lensrt:spp", "4"}, {"lensrt:version", "test"}});
    const Image stored = readImage(dir / f.file);
    ASSERT_EQ(stored.width, 40);
    ASSERT_EQ(stored.height, 33);
    ASSERT_EQ(stored.channels, (std::vector<std::string>{"R", "G", "B"}));
    const Image linear = readLinearImage(dir / f.file);
    for (const int y : {5, 16, 27}) {
      const float v = image.at(3, y, 0);
      const double code = f.log ? std::round(cineonEncode(v)) : std::round(srgbEncode(v) * f.full);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(stored.at(3, y, c) * f.full, code, f.tolerance) << y;
      const double expected = f.log ? v : std::min(v, 1.0f);  // display-referred files clip at white
      EXPECT_NEAR(linear.at(3, y, 1), expected, f.linearTolerance * expected) << y;
    }
  }
}

TEST(PluginImageIo, FilesAreRecognisedByTheirContent) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const ScratchDir dir;
  for (const FormatCase& f : kFormats) {
    SCOPED_TRACE(f.file);
    writeImage(dir / f.file, greyRows(), {});
    fs::rename(dir / f.file, dir / "renamed.img");
    const Image fromFile = readImage(dir / "renamed.img");
    const Image fromBytes = decodeImage(test::readFileBytes(dir / "renamed.img"), "bytes");
    EXPECT_EQ(fromFile.width, 40);
    EXPECT_EQ(fromBytes.pixels, fromFile.pixels);
  }
}

TEST(PluginImageIo, DeclaredSizesAreReadFromWebPAndJpeg2000Headers) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const ScratchDir dir;
  for (const char* file : {"a.webp", "a.jp2", "a.j2k"}) {
    writeImage(dir / file, greyRows(), {});
    const std::string bytes = test::readFileBytes(dir / file);
    const auto size =
        pluginFormatDeclaredSize(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    ASSERT_TRUE(size) << file;
    EXPECT_EQ(size->width, 40u) << file;
    EXPECT_EQ(size->height, 33u) << file;
  }
}

// A VP8L (lossless WebP) header declaring 16384x16384 over a few bytes of
// data: refused on its header, not after the decoder allocated 1 GiB.
TEST(PluginImageIo, AWebPHeaderDeclaringAHugeImageIsRefusedBeforeDecoding) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  std::string webp = "RIFF";
  webp += std::string("\x20\x00\x00\x00", 4);
  webp += "WEBPVP8L";
  webp += std::string("\x14\x00\x00\x00", 4);
  webp += std::string("\x2f\xff\xff\xff\x0f", 5);  // 14-bit width-1 and height-1 all ones
  webp += std::string(15, '\0');
  try {
    decodeImage(webp, "huge.webp", nullptr, 1 << 22);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "the image is 16384x16384 with 4 channels, more than 4194304 values");
  }
}

// A cut DPX file too, which OpenImageIO 2.4 reads without complaint (the
// rest of its pixels uninitialised): its header's file size refuses it.
TEST(PluginImageIo, ACutFileIsAnInputError) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const ScratchDir dir;
  for (const char* file : {"a.tif", "a.dpx", "a.webp", "a.jp2"}) {
    writeImage(dir / file, greyRows(), {});
    const std::string bytes = test::readFileBytes(dir / file);
    for (const std::size_t keep : {std::size_t(8), bytes.size() / 2}) {
      try {
        decodeImage(bytes.substr(0, keep), file);
        FAIL() << "expected InputError: " << file << " cut to " << keep;
      } catch (const InputError& e) {
        EXPECT_EQ(e.message().rfind("cannot read image: ", 0), 0u) << e.message();
      }
    }
  }
  std::ofstream(dir / "cut.dpx", std::ios::binary) << test::readFileBytes(dir / "a.dpx").substr(0, 5000);
  try {
    readImage(dir / "cut.dpx");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(),
              "cannot read image: the DPX file is cut short: its header declares 13472 bytes, it "
              "holds 5000");
  }
}

}  // namespace
}  // namespace lensrt
