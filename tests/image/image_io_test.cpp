#include "image/image_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include "core/error.h"
#include "image/srgb.h"
#include "image_test_util.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

// A render-like image: beauty, alpha and AOVs with distinct values per pixel
// and channel, so a swapped channel or flipped row shows.
Image renderLikeImage() {
  Image image(5, 3, {"R", "G", "B", "A", "depth.Z", "normal.X", "variance.R"});
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < int(image.channelCount()); ++c)
        image.at(x, y, c) = 0.125f * c + 1.5f * x - 3.25f * y;
  return image;
}

TEST(ImageIo, ExrRoundTripKeepsChannelsValuesAndMetadata) {
  const ScratchDir dir;
  const Image original = renderLikeImage();
  const ImageMetadata metadata{{"lensrt:spp", "64"}, {"lensrt:camera", "thin lens f/2.8"}};
  writeImage(dir / "a.exr", original, metadata);

  ImageMetadata readBack;
  const Image image = readImage(dir / "a.exr", &readBack);
  ASSERT_EQ(image.width, original.width);
  ASSERT_EQ(image.height, original.height);
  ASSERT_EQ(image.channelCount(), original.channelCount());
  // EXR may reorder channels: match them by name.
  for (int c = 0; c < int(original.channelCount()); ++c) {
    const int k = image.channelIndex(original.channels[c]);
    ASSERT_GE(k, 0) << original.channels[c];
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) EXPECT_EQ(image.at(x, y, k), original.at(x, y, c));
  }
  EXPECT_EQ(readBack["lensrt:spp"], "64");
  EXPECT_EQ(readBack["lensrt:camera"], "thin lens f/2.8");
  EXPECT_EQ(readBack["compression"], "zip");
}

TEST(ImageIo, MetadataReadFromAnExrCanBeWrittenBack) {
  // What readImage reports includes the header's own attributes
  // (compression, PixelAspectRatio, DateTime, ...): tools that read, change
  // and rewrite a render pass it back unchanged.
  const test::ScratchDir dir;
  writeImage(dir / "a.exr", renderLikeImage(), {{"lensrt:spp", "64"}});
  ImageMetadata first;
  const Image image = readImage(dir / "a.exr", &first);
  ASSERT_TRUE(first.count("DateTime"));
  writeImage(dir / "b.exr", image, first);
  ImageMetadata second;
  readImage(dir / "b.exr", &second);
  EXPECT_EQ(second, first);
}

TEST(ImageIo, ExrKeepsTheDataWindowOfACrop) {
  const test::ScratchDir dir;
  Image crop = test::constantImage(3, 2, {"R"}, 0.0f);
  crop.at(2, 1, 0) = 7.0f;
  crop.originX = 4;
  crop.originY = 1;
  crop.frameWidth = 10;
  crop.frameHeight = 6;
  writeImage(dir / "c.exr", crop, {});
  const Image back = readImage(dir / "c.exr");
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.originX, 4);
  EXPECT_EQ(back.originY, 1);
  EXPECT_EQ(back.fullWidth(), 10);
  EXPECT_EQ(back.fullHeight(), 6);
  EXPECT_EQ(back.at(2, 1, 0), 7.0f);
}

TEST(ImageIo, RadianceHdrIsReadAsLinearValues) {
  // Two flat RGBE pixels: (192,128,64) * 2^(130-136) = (3, 2, 1) and
  // 128 * 2^(120-136) = 2^-9.
  const test::ScratchDir dir;
  std::ofstream(dir / "t.hdr", std::ios::binary)
      << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n"
      << std::string{char(192), char(128), char(64), char(130), char(128), char(128), char(128), char(120)};
  const Image hdr = readImage(dir / "t.hdr");
  ASSERT_EQ(hdr.channels, (std::vector<std::string>{"R", "G", "B"}));
  EXPECT_EQ(hdr.at(0, 0, 0), 3.0f);
  EXPECT_EQ(hdr.at(0, 0, 1), 2.0f);
  EXPECT_EQ(hdr.at(0, 0, 2), 1.0f);
  EXPECT_EQ(hdr.at(1, 0, 1), 1.0f / 512.0f);
}

TEST(ImageIo, HalfExrRoundsToElevenSignificantBits) {
  const ScratchDir dir;
  Image original = test::constantImage(2, 1, {"R", "G", "B"}, 0.0f);
  original.at(0, 0, 0) = 1.0f + 1.0f / 4096.0f;  // below half's 2^-10 step: rounds to 1
  original.at(1, 0, 1) = 1000.0f;                // exactly representable
  ImageWriteOptions half;
  half.halfFloat = true;
  writeImage(dir / "h.exr", original, {}, half);
  const Image image = readImage(dir / "h.exr");
  EXPECT_EQ(image.at(0, 0, image.channelIndex("R")), 1.0f);
  EXPECT_EQ(image.at(1, 0, image.channelIndex("G")), 1000.0f);
}

TEST(ImageIo, PngStoresSrgbEncodedEightBitValues) {
  const ScratchDir dir;
  const float linear[] = {0.0f, 0.001f, 0.0031308f, 0.18f, 0.5f, 1.0f, 2.0f, -1.0f};
  Image original(8, 1, {"R", "G", "B", "A"});
  for (int x = 0; x < 8; ++x) {
    original.at(x, 0, 0) = linear[x];
    original.at(x, 0, 1) = linear[7 - x];
    original.at(x, 0, 2) = 0.5f;
    original.at(x, 0, 3) = 0.25f;  // alpha is not part of the preview
  }
  writeImage(dir / "p.png", original, {});
  const Image png = readImage(dir / "p.png");
  ASSERT_EQ(png.channelCount(), 3u);
  // The closed-form sRGB OETF, written out independently of srgb.h.
  const auto expectedCode = [](double v) {
    v = std::fmin(std::fmax(v, 0.0), 1.0);
    const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return std::round(e * 255);
  };
  for (int x = 0; x < 8; ++x) {
    EXPECT_EQ(std::round(png.at(x, 0, 0) * 255), expectedCode(linear[x])) << "x=" << x;
    EXPECT_EQ(std::round(png.at(x, 0, 1) * 255), expectedCode(linear[7 - x])) << "x=" << x;
  }
  // Known codes: 18% grey is 118, half is 188.
  EXPECT_EQ(std::round(png.at(3, 0, 0) * 255), 118);
  EXPECT_EQ(std::round(png.at(4, 0, 0) * 255), 188);
}

TEST(ImageIo, SrgbDecodeInvertsEncode) {
  for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-6f);
}

TEST(ImageIo, JpegPreviewIsCloseToSrgbValues) {
  const ScratchDir dir;
  writeImage(dir / "p.jpg", test::constantImage(16, 16, {"R", "G", "B"}, 0.18f), {});
  const Image jpg = readImage(dir / "p.jpg");
  // JPEG is lossy but a flat field survives to within a code or two.
  EXPECT_NEAR(jpg.at(7, 7, 1) * 255, 118, 2);
}

void expectUntouchedAndNoStrays(const ScratchDir& dir, const fs::path& target, const std::string& before) {
  EXPECT_EQ(test::readFileBytes(target), before);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{target.filename().string()});
}

TEST(ImageIo, UnknownExtensionLeavesExistingFileAlone) {
  const ScratchDir dir;
  const fs::path target = dir / "out.tga";
  std::ofstream(target) << "precious";
  try {
    writeImage(target, test::constantImage(2, 2, {"R", "G", "B"}, 1.0f), {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), target.string());
    EXPECT_NE(e.message().find("unknown image extension"), std::string::npos) << e.message();
  }
  expectUntouchedAndNoStrays(dir, target, "precious");
}

TEST(ImageIo, MissingDirectoryIsReported) {
  const ScratchDir dir;
  try {
    writeImage(dir / "no/such/dir/out.exr", test::constantImage(2, 2, {"R"}, 1.0f), {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("directory does not exist"), std::string::npos) << e.message();
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(ImageIo, ReadOnlyDirectoryLeavesExistingFileAlone) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: directory permissions do not apply";
  const ScratchDir dir;
  const fs::path target = dir / "out.exr";
  writeImage(target, test::constantImage(2, 2, {"R"}, 1.0f), {});
  const std::string before = test::readFileBytes(target);
  fs::permissions(dir.path(), fs::perms::owner_write | fs::perms::group_write | fs::perms::others_write,
                  fs::perm_options::remove);
  try {
    writeImage(target, test::constantImage(2, 2, {"R"}, 7.0f), {});
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("permission denied"), std::string::npos) << e.message();
  }
  fs::permissions(dir.path(), fs::perms::owner_all, fs::perm_options::add);
  expectUntouchedAndNoStrays(dir, target, before);
}

TEST(ImageIo, UncreatableDirectoryIsReportedEvenForRoot) {
  // /proc refuses new files for every user, root included.
  if (!fs::is_directory("/proc/self")) GTEST_SKIP() << "no /proc on this system";
  EXPECT_THROW(writeImage("/proc/lensrt_test_out.exr", test::constantImage(1, 1, {"R"}, 1.0f), {}),
               InputError);
}

TEST(ImageIo, InconsistentImageLeavesExistingFileAlone) {
  const ScratchDir dir;
  const fs::path target = dir / "out.exr";
  writeImage(target, test::constantImage(2, 2, {"R"}, 1.0f), {});
  const std::string before = test::readFileBytes(target);
  Image broken = test::constantImage(2, 2, {"R"}, 5.0f);
  broken.pixels.pop_back();
  EXPECT_THROW(writeImage(target, broken, {}), InputError);
  expectUntouchedAndNoStrays(dir, target, before);
}

TEST(ImageIo, OverwriteReplacesTheFile) {
  const ScratchDir dir;
  const fs::path target = dir / "out.exr";
  writeImage(target, test::constantImage(2, 2, {"R"}, 1.0f), {});
  writeImage(target, test::constantImage(2, 2, {"R"}, 3.0f), {});
  EXPECT_EQ(readImage(target).at(1, 1, 0), 3.0f);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.exr"});
}

TEST(ImageIo, UnreadableFilesThrowInputError) {
  const ScratchDir dir;
  EXPECT_THROW(readImage(dir / "missing.exr"), InputError);
  std::ofstream(dir / "garbage.exr") << "not an image";
  EXPECT_THROW(readImage(dir / "garbage.exr"), InputError);
  EXPECT_THROW(readImage(dir.path()), InputError);
}

// A header attribute claiming more bytes than the file holds is refused
// before OpenEXR allocates them (the fuzzer's 1.8 GB from a 600-byte file),
// read from a file or from memory.
TEST(ImageIo, ExrAttributeLargerThanTheFileIsRefused) {
  const ScratchDir dir;
  writeImage(dir / "good.exr", renderLikeImage(), {});
  std::string bytes;
  {
    std::ifstream in(dir / "good.exr", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // The first attribute's size field follows its name and type names.
  const std::size_t name = 8, type = bytes.find('\0', name) + 1, size = bytes.find('\0', type) + 1;
  ASSERT_LT(size + 4, bytes.size());
  const std::uint32_t huge = 0x70000000u;
  for (int i = 0; i < 4; ++i) bytes[size + std::size_t(i)] = char((huge >> (8 * i)) & 0xff);
  std::ofstream(dir / "huge-attribute.exr", std::ios::binary) << bytes;
  for (const auto& read :
       {std::function<Image()>([&] { return readImage(dir / "huge-attribute.exr"); }),
        std::function<Image()>([&] { return decodeImage(bytes, "mem.exr", nullptr, 1u << 22); })}) {
    try {
      read();
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("claims 1879048192 bytes, more than the file has left"),
                std::string::npos)
          << e.what();
    }
  }
}

// OpenEXR's C++ reader takes most attributes by their type, not by their
// size field (the fuzzer hid 2 GB strings behind a channel list and a
// compression attribute whose sizes lied): such sizes must be exact, a
// preview's pixels must fill it, and names stop at 255 characters.
TEST(ImageIo, ExrHeaderWalkFollowsOpenExrsReaders) {
  const auto u32 = [](std::uint32_t v) {
    std::string b(4, '\0');
    for (int i = 0; i < 4; ++i) b[std::size_t(i)] = char((v >> (8 * i)) & 0xff);
    return b;
  };
  const auto attribute = [&](const std::string& name, const std::string& type, std::uint32_t size,
                             const std::string& value) {
    return name + '\0' + type + '\0' + u32(size) + value;
  };
  const std::string magic = std::string("\x76\x2f\x31\x01", 4) + u32(2);
  const std::string channel = std::string("R") + '\0' + u32(2) + u32(0) + u32(1) + u32(1);
  const std::string hidden = magic + attribute("channels", "chlist", 1, channel + '\0') +
                             attribute("comment", "string", 0x70000000u, "") + '\0';
  const std::string preview = magic + attribute("preview", "preview", 8, u32(60000) + u32(60000)) + '\0';
  const std::string longName = magic + attribute(std::string(300, 'n'), "int", 4, u32(0)) + '\0';
  const std::string compression =
      magic + attribute("squeeze", "compression", 256, std::string(256, '\0')) + '\0';
  const std::pair<std::string, std::string> cases[] = {
      {hidden, "'channels' has a channel list that does not fill its 1 bytes"},
      {compression, "'squeeze' of type compression has 256 bytes, not 1"},
      {preview, "'preview' has a preview image whose size does not match its 8 bytes"},
      {longName, "longer than 255 characters"}};
  for (const auto& [bytes, message] : cases) {
    try {
      decodeImage(bytes, "walk.exr", nullptr, 1u << 22);
      ADD_FAILURE() << "accepted: " << message;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

// Radiance run-length data: runs and literal chunks decode (RGBE 128,64,32,
// exponent 129 is 1.0, 0.5, 0.25), a chunk of length 0 (on which stb_image
// spins forever) and data ending early are refused, however stb_image
// reads the header.
TEST(ImageIo, RadianceRunLengthScanlines) {
  const auto hdr = [](const std::string& scanline) {
    return std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n") + scanline;
  };
  std::string good("\x02\x02\x00\x08", 4);
  for (const char v : {char(128), char(64), char(32)}) good += std::string("\x88") + v;  // a run of 8
  good += std::string("\x08") + std::string(8, char(129));                               // 8 literals
  const Image image = decodeImage(hdr(good), "rle.hdr");
  ASSERT_EQ(image.width, 8);
  EXPECT_FLOAT_EQ(image.at(7, 0, 0), 1.0f);
  EXPECT_FLOAT_EQ(image.at(3, 0, 1), 0.5f);
  EXPECT_FLOAT_EQ(image.at(0, 0, 2), 0.25f);
  const std::string zero("\x02\x02\x00\x08\x00", 5);
  const std::string early("\x02\x02\x00\x08\x88", 5);
  // stb_image ends the header at a line that starts with a NUL byte (found by
  // the fuzzer: a check that looked for an empty line missed this scanline).
  const std::string nulLine = std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n") + '\0' + "x\n-Y 1 +X 8\n" +
                              zero.substr(0, 4) + "\x88";
  // At width 256 the scanline length's low byte may be missing: stb_image
  // reads 0 there, which matches, and then spins on zero counts.
  const std::string wide =
      std::string("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 256\n") + "\x02\x02\x01";
  for (const std::string& bad : {hdr(zero), hdr(early), nulLine, wide}) {
    try {
      decodeImage(bad, "bad.hdr");
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("Radiance"), std::string::npos) << e.what();
    }
  }
}

TEST(ImageIo, WritableExtensions) {
  EXPECT_TRUE(isWritableImageExtension("a.EXR"));
  EXPECT_TRUE(isWritableImageExtension("dir/a.jpeg"));
  EXPECT_TRUE(isWritableImageExtension("a.tiff"));
  EXPECT_TRUE(isWritableImageExtension("a.DPX"));
  EXPECT_TRUE(isWritableImageExtension("a.jp2"));
  EXPECT_TRUE(isWritableImageExtension("a.webp"));
  EXPECT_FALSE(isWritableImageExtension("a.tga"));
  EXPECT_FALSE(isWritableImageExtension("a"));
}

}  // namespace
}  // namespace lensrt
