#include "image/plugin_image_formats.h"

#include <algorithm>
#include <cstring>

namespace lensrt {
namespace {

bool startsWith(const unsigned char* bytes, std::size_t size, const char* magic, std::size_t n,
                std::size_t at = 0) {
  return size >= at + n && std::memcmp(bytes + at, magic, n) == 0;
}

std::uint32_t bigEndian32(const unsigned char* b) {
  return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | b[3];
}

std::uint32_t littleEndian(const unsigned char* b, int bytes) {
  std::uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | b[i];
  return v;
}

constexpr char kJp2Signature[] = "\x00\x00\x00\x0cjP  \r\n\x87\n";
constexpr char kJ2kCodestream[] = "\xff\x4f\xff\x51";

// WebP: the first chunk after "RIFF" size "WEBP" says the canvas size:
// lossy VP8 (14-bit width and height after the key frame's start code),
// lossless VP8L (14-bit width-1 and height-1 after its signature byte) or
// the extended VP8X (24-bit width-1 and height-1).
std::optional<DeclaredImageSize> webpSize(const unsigned char* b, std::size_t n) {
  if (n < 30) return std::nullopt;
  if (std::memcmp(b + 12, "VP8 ", 4) == 0) {
    if (b[23] != 0x9d || b[24] != 0x01 || b[25] != 0x2a) return std::nullopt;
    return DeclaredImageSize{littleEndian(b + 26, 2) & 0x3fff, littleEndian(b + 28, 2) & 0x3fff, 4};
  }
  if (std::memcmp(b + 12, "VP8L", 4) == 0) {
    if (b[20] != 0x2f) return std::nullopt;
    const std::uint32_t bits = littleEndian(b + 21, 4);
    return DeclaredImageSize{(bits & 0x3fff) + 1, ((bits >> 14) & 0x3fff) + 1, 4};
  }
  if (std::memcmp(b + 12, "VP8X", 4) == 0)
    return DeclaredImageSize{littleEndian(b + 24, 3) + 1, littleEndian(b + 27, 3) + 1, 4};
  return std::nullopt;
}

// A JPEG 2000 codestream's SIZ segment: the reference grid's extent less
// the image offset, and the component count.
std::optional<DeclaredImageSize> codestreamSize(const unsigned char* b, std::size_t n) {
  if (n < 42 || !startsWith(b, n, kJ2kCodestream, 4)) return std::nullopt;
  const std::uint32_t xsiz = bigEndian32(b + 8), ysiz = bigEndian32(b + 12);
  const std::uint32_t xosiz = bigEndian32(b + 16), yosiz = bigEndian32(b + 20);
  if (xosiz >= xsiz || yosiz >= ysiz) return std::nullopt;
  return DeclaredImageSize{xsiz - xosiz, ysiz - yosiz, (std::uint32_t{b[40]} << 8) | b[41]};
}

// A JP2 file's boxes: the image header (in the jp2h superbox) and the
// codestream (jp2c) each declare a size, and the decoder trusts either.
std::optional<DeclaredImageSize> jp2Size(const unsigned char* b, std::size_t n) {
  std::optional<DeclaredImageSize> found;
  const auto merge = [&](const DeclaredImageSize& s) {
    if (!found) found = s;
    found->width = std::max(found->width, s.width);
    found->height = std::max(found->height, s.height);
    found->channels = std::max(found->channels, s.channels);
  };
  // Walks the boxes in [at, end); descends into jp2h.
  const auto walk = [&](auto&& self, std::size_t at, std::size_t end) -> void {
    while (at + 8 <= end) {
      std::uint64_t length = bigEndian32(b + at);
      std::size_t header = 8;
      if (length == 1) {
        if (at + 16 > end) return;
        length = (std::uint64_t{bigEndian32(b + at + 8)} << 32) | bigEndian32(b + at + 12);
        header = 16;
      } else if (length == 0) {
        length = end - at;
      }
      if (length < header) return;
      const std::size_t boxEnd = length > end - at ? end : at + std::size_t(length);
      const unsigned char* type = b + at + 4;
      if (std::memcmp(type, "jp2h", 4) == 0) {
        self(self, at + header, boxEnd);
      } else if (std::memcmp(type, "ihdr", 4) == 0 && boxEnd - at >= header + 10) {
        const unsigned char* d = b + at + header;
        merge({bigEndian32(d + 4), bigEndian32(d), (std::uint32_t{d[8]} << 8) | d[9]});
      } else if (std::memcmp(type, "jp2c", 4) == 0) {
        if (const auto s = codestreamSize(b + at + header, boxEnd - at - header)) merge(*s);
      }
      if (length > end - at) return;
      at += std::size_t(length);
    }
  };
  walk(walk, 0, n);
  return found;
}

}  // namespace

std::optional<PluginFormat> sniffPluginFormat(const unsigned char* bytes, std::size_t size) {
  if (startsWith(bytes, size, "RIFF", 4) && startsWith(bytes, size, "WEBP", 4, 8))
    return PluginFormat{"webp", "WebP"};
  if (startsWith(bytes, size, "II*\0", 4) || startsWith(bytes, size, "MM\0*", 4) ||
      startsWith(bytes, size, "II+\0", 4) || startsWith(bytes, size, "MM\0+", 4))  // BigTIFF
    return PluginFormat{"tiff", "TIFF"};
  if (startsWith(bytes, size, kJp2Signature, 12) || startsWith(bytes, size, kJ2kCodestream, 4))
    return PluginFormat{"jpeg2000", "JPEG 2000"};
  if (startsWith(bytes, size, "SDPX", 4) || startsWith(bytes, size, "XPDS", 4))
    return PluginFormat{"dpx", "DPX"};
  return std::nullopt;
}

std::optional<DeclaredImageSize> pluginFormatDeclaredSize(const unsigned char* bytes, std::size_t size) {
  const std::optional<PluginFormat> format = sniffPluginFormat(bytes, size);
  if (!format) return std::nullopt;
  if (std::strcmp(format->name, "webp") == 0) return webpSize(bytes, size);
  if (std::strcmp(format->name, "jpeg2000") == 0)
    return startsWith(bytes, size, kJ2kCodestream, 4) ? codestreamSize(bytes, size) : jp2Size(bytes, size);
  return std::nullopt;
}

}  // namespace lensrt
