#include "image/stb_io.h"

#include <stb_image.h>
#include <stb_image_write.h>
#include <zlib.h>

#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/png_allocation.h"

namespace lensrt {
namespace {

void appendToString(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

void appendBigEndian(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((v >> shift) & 0xff));
}

// One PNG chunk: length, type, data, CRC-32 of type and data.
std::string pngChunk(const char (&type)[5], const std::string& data) {
  std::string chunk;
  appendBigEndian(chunk, std::uint32_t(data.size()));
  const std::string body = std::string(type, 4) + data;
  chunk += body;
  appendBigEndian(chunk,
                  std::uint32_t(crc32(0L, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
  return chunk;
}

bool isAscii(const std::string& s) {
  for (const char c : s)
    if (static_cast<unsigned char>(c) >= 0x80 || c == '\0') return false;
  return true;
}

// The metadata as text chunks, as OpenImageIO wrote them: tEXt holds
// Latin-1, so values with other bytes go into iTXt (UTF-8, uncompressed).
// PNG keywords are 1 to 79 printable characters; others are left out.
std::string textChunks(const ImageMetadata& metadata) {
  std::string chunks;
  for (const auto& [key, value] : metadata) {
    if (key.empty() || key.size() > 79 || !isAscii(key) || key.front() == ' ' || key.back() == ' ') continue;
    if (value.find('\0') != std::string::npos) continue;
    if (isAscii(value))
      chunks += pngChunk("tEXt", key + '\0' + value);
    else  // keyword, 0, compression flag 0, method 0, no language, no translated keyword
      chunks += pngChunk("iTXt", key + std::string(1, '\0') + '\0' + '\0' + '\0' + '\0' + value);
  }
  return chunks;
}

struct StbFree {
  void operator()(void* p) const { stbi_image_free(p); }
};

std::string failure(const char* what) {
  const char* reason = stbi_failure_reason();
  return std::string(what) + ": " + (reason ? reason : "unknown error") +
         " (lensrt reads EXR, PNG, JPEG, HDR, BMP, TGA, PSD, GIF, PIC and PNM images)";
}

}  // namespace

std::string encodePreview(const std::string& name, PreviewFormat format, int width, int height,
                          const std::string& rgb, const ImageMetadata& metadata) {
  std::string bytes;
  const bool ok =
      format == PreviewFormat::Png
          ? stbi_write_png_to_func(appendToString, &bytes, width, height, 3, rgb.data(), width * 3)
          : stbi_write_jpg_to_func(appendToString, &bytes, width, height, 3, rgb.data(), 95);
  if (!ok || bytes.empty()) throw InputError(name, "cannot write: the image could not be encoded");
  // stb writes the signature (8 bytes), then IHDR (25): text goes after it.
  constexpr std::size_t kAfterHeader = 8 + 25;
  if (format == PreviewFormat::Png && bytes.size() > kAfterHeader)
    bytes.insert(kAfterHeader, textChunks(metadata));
  return bytes;
}

// stb_image's Radiance decoder loops forever on a run-length scanline whose
// count byte is 0: it never advances, and past the end of the data every byte
// reads 0, so data ending inside such a scanline spins too. The fuzzer found
// .hdr files that hung `lensrt diff`. Read the file exactly the way
// stbi__hdr_load will (its header tokens, its resolution line, 0 past the
// end) and refuse such counts first; whatever stb_image reports as an error or
// decodes as flat (old-style) data is left to it.
void checkRadianceRunLengths(std::string_view bytes, const std::string& name) {
  std::size_t pos = 0;
  const auto get8 = [&]() -> int {  // stbi__get8
    return pos < bytes.size() ? static_cast<unsigned char>(bytes[pos++]) : 0;
  };
  const auto atEof = [&] { return pos >= bytes.size(); };
  const auto token = [&] {  // stbi__hdr_gettoken: a C string, so it ends at a NUL
    constexpr std::size_t kBufferLength = 1024;
    std::string t;
    char c = char(get8());
    while (!atEof() && c != '\n') {
      t.push_back(c);
      if (t.size() == kBufferLength - 1) {
        while (!atEof() && get8() != '\n') {
        }
        break;
      }
      c = char(get8());
    }
    return std::string(t.c_str());
  };
  if (const std::string id = token(); id != "#?RADIANCE" && id != "#?RGBE") return;
  while (!token().empty()) {
  }
  const std::string resolution = token();
  if (resolution.compare(0, 3, "-Y ") != 0) return;
  char* rest = nullptr;
  const int height = int(std::strtol(resolution.c_str() + 3, &rest, 10));
  while (*rest == ' ') ++rest;
  if (std::strncmp(rest, "+X ", 3) != 0) return;
  const int width = int(std::strtol(rest + 3, nullptr, 10));
  if (width < 8 || width >= 32768 || height <= 0 || height > (1 << 24)) return;  // flat data or an error
  for (int y = 0; y < height; ++y) {
    const int c1 = get8(), c2 = get8(), high = get8();
    if (c1 != 2 || c2 != 2 || (high & 0x80)) return;  // flat from here on
    if (((high << 8) | get8()) != width) return;      // stb reports it
    for (int k = 0; k < 4; ++k)
      for (int x = 0; x < width;) {
        int count = get8();
        if (count > 128) {
          count -= 128;
          get8();
        } else {
          for (int j = 0; j < count; ++j) get8();
        }
        if (count == 0)
          throw InputError(name, pos >= bytes.size() ? "cannot decode image: the Radiance data ends early"
                                                     : "cannot decode image: a Radiance run of length 0");
        if (count > width - x) return;  // stb reports it
        x += count;
      }
  }
}

std::optional<StbCodes> decodeStbCodes(std::string_view bytes) {
  if (bytes.empty() || bytes.size() > std::size_t(INT_MAX)) return std::nullopt;
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = int(bytes.size());
  constexpr int kRgba = 4;
  StbCodes codes;
  int w = 0, h = 0, c = 0;
  std::unique_ptr<unsigned char, StbFree> pixels;
  if (stbi_is_16_bit_from_memory(data, length)) {
    pixels.reset(reinterpret_cast<unsigned char*>(stbi_load_16_from_memory(data, length, &w, &h, &c, kRgba)));
    if (pixels) codes.bits = 16;
  }
  if (!pixels) pixels.reset(stbi_load_from_memory(data, length, &w, &h, &c, kRgba));
  if (!pixels || w < 1 || h < 1) return std::nullopt;
  codes.width = w;
  codes.height = h;
  codes.components = kRgba;
  const std::size_t size = std::size_t(w) * std::size_t(h) * kRgba * std::size_t(codes.bits / 8);
  codes.data.assign(pixels.get(), pixels.get() + size);
  return codes;
}

bool isStbImage(std::string_view bytes) {
  int width = 0, height = 0, channels = 0;
  return bytes.size() <= std::size_t(INT_MAX) &&
         stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &width,
                               &height, &channels);
}

Image decodeStbImage(std::string_view bytes, const std::string& name, std::size_t maxValues) {
  if (bytes.size() > std::size_t(INT_MAX)) throw InputError(name, "the image file is larger than 2 GiB");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = int(bytes.size());
  // Before stb_image allocates what a lying PNG claims (image/png_allocation.h).
  if (const std::optional<std::string> problem = pngAllocationProblem(data, bytes.size()))
    throw InputError(name, "cannot decode image: " + *problem);
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, length, &width, &height, &channels))
    throw InputError(name, failure("cannot read image"));
  if (width <= 0 || height <= 0 || channels < 1 || channels > 4)
    throw InputError(name, "cannot read image: unsupported size or channel count");
  if (double(width) * double(height) * double(channels) > double(maxValues))
    throw InputError(name, "the image is " + std::to_string(width) + "x" + std::to_string(height) + " with " +
                               std::to_string(channels) + " channels, more than " +
                               std::to_string(maxValues) + " values");

  static const std::vector<std::string> kNames[4] = {
      {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  int w = 0, h = 0, c = 0;
  Image image;
  const auto fill = [&](auto* pixels, float full) {
    if (!pixels) throw InputError(name, failure("cannot decode image"));
    if (w != width || h != height || c != channels)
      throw InputError(name, "cannot decode image: the header and the pixels disagree");
    image = Image(w, h, kNames[c - 1]);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(pixels[i]) / full;
  };
  if (stbi_is_hdr_from_memory(data, length)) {
    checkRadianceRunLengths(bytes, name);
    const std::unique_ptr<float, StbFree> pixels(stbi_loadf_from_memory(data, length, &w, &h, &c, 0));
    fill(pixels.get(), 1.0f);
  } else if (stbi_is_16_bit_from_memory(data, length)) {
    const std::unique_ptr<stbi_us, StbFree> pixels(stbi_load_16_from_memory(data, length, &w, &h, &c, 0));
    fill(pixels.get(), 65535.0f);
  } else {
    const std::unique_ptr<stbi_uc, StbFree> pixels(stbi_load_from_memory(data, length, &w, &h, &c, 0));
    fill(pixels.get(), 255.0f);
  }
  return image;
}

}  // namespace lensrt
