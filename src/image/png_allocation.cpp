#include "image/png_allocation.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace lensrt {
namespace {

std::uint32_t bigEndian32(const unsigned char* b) {
  return (std::uint32_t{b[0]} << 24) | (std::uint32_t{b[1]} << 16) | (std::uint32_t{b[2]} << 8) | b[3];
}

// Bytes of the filtered scanlines a non-interlaced image holds; Adam7 adds a
// filter byte per row of each of its seven passes and at most a partial byte.
std::uint64_t maxRawBytes(std::uint32_t width, std::uint32_t height, unsigned bitsPerPixel) {
  const std::uint64_t row = (std::uint64_t{width} * bitsPerPixel + 7) / 8;
  return std::uint64_t{height} * (row + 1) + 7 * (std::uint64_t{height} + 1) * 2;
}

constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

}  // namespace

std::optional<std::pair<std::uint32_t, std::uint32_t>> pngDeclaredSize(const unsigned char* b,
                                                                       std::size_t n) {
  if (n < 24 || !std::equal(kSignature, kSignature + 8, b) || !std::equal(b + 12, b + 16, "IHDR"))
    return std::nullopt;
  return std::pair{bigEndian32(b + 16), bigEndian32(b + 20)};
}

std::optional<std::string> pngAllocationProblem(const unsigned char* b, std::size_t n) {
  if (n < 33 || !std::equal(kSignature, kSignature + 8, b)) return std::nullopt;
  std::uint32_t width = 0, height = 0;
  unsigned bitsPerPixel = 0;
  std::vector<unsigned char> idat;
  for (std::size_t at = 8; at + 12 <= n;) {
    const std::uint64_t length = bigEndian32(b + at);
    if (at + 12 + length > n)
      return "chunk '" + std::string(reinterpret_cast<const char*>(b + at + 4), 4) + "' claims " +
             std::to_string(length) + " bytes, more than the file holds: not decoded";
    const unsigned char* type = b + at + 4;
    const unsigned char* data = b + at + 8;
    if (std::equal(type, type + 4, "IHDR") && length >= 13) {
      width = bigEndian32(data);
      height = bigEndian32(data + 4);
      const unsigned depth = data[8], colour = data[9];
      const unsigned channels = colour == 2 ? 3 : colour == 4 ? 2 : colour == 6 ? 4 : 1;
      bitsPerPixel = channels * depth;
    } else if (std::equal(type, type + 4, "IDAT")) {
      idat.insert(idat.end(), data, data + length);
    } else if (std::equal(type, type + 4, "IEND")) {
      break;
    }
    at += 12 + length;
  }
  if (idat.empty() || bitsPerPixel == 0) return std::nullopt;
  const std::uint64_t limit = maxRawBytes(width, height, bitsPerPixel);

  z_stream z{};
  if (inflateInit(&z) != Z_OK) return std::nullopt;
  z.next_in = idat.data();
  z.avail_in = static_cast<uInt>(std::min<std::size_t>(idat.size(), UINT32_MAX));
  std::array<unsigned char, 1 << 16> scratch{};
  std::uint64_t total = 0;
  int status = Z_OK;
  while (status == Z_OK && total <= limit) {
    z.next_out = scratch.data();
    z.avail_out = scratch.size();
    status = inflate(&z, Z_NO_FLUSH);
    total += scratch.size() - z.avail_out;
    if (status == Z_BUF_ERROR && z.avail_in == 0) break;  // the data ends early: the decoder's to report
  }
  inflateEnd(&z);
  if (total <= limit) return std::nullopt;
  return "its image data inflates beyond the " + std::to_string(width) + "x" + std::to_string(height) +
         " pixels its header declares (more than " + std::to_string(limit) + " bytes): not decoded";
}

}  // namespace lensrt
