#include "core/murmur_hash.h"

#include <bit>
#include <cstring>

namespace lensrt {

std::uint32_t murmurHash3X86_32(std::string_view bytes, std::uint32_t seed) {
  constexpr std::uint32_t c1 = 0xcc9e2d51, c2 = 0x1b873593;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size(), blocks = n / 4;
  std::uint32_t h = seed;
  for (std::size_t i = 0; i < blocks; ++i) {
    std::uint32_t k = std::uint32_t(data[4 * i]) | std::uint32_t(data[4 * i + 1]) << 8 |
                      std::uint32_t(data[4 * i + 2]) << 16 | std::uint32_t(data[4 * i + 3]) << 24;
    k *= c1;
    k = std::rotl(k, 15);
    k *= c2;
    h ^= k;
    h = std::rotl(h, 13);
    h = h * 5 + 0xe6546b64;
  }
  const unsigned char* tail = data + 4 * blocks;
  std::uint32_t k = 0;
  switch (n & 3) {
    case 3:
      k ^= std::uint32_t(tail[2]) << 16;
      [[fallthrough]];
    case 2:
      k ^= std::uint32_t(tail[1]) << 8;
      [[fallthrough]];
    case 1:
      k ^= tail[0];
      k *= c1;
      k = std::rotl(k, 15);
      k *= c2;
      h ^= k;
  }
  h ^= std::uint32_t(n);
  h ^= h >> 16;
  h *= 0x85ebca6b;
  h ^= h >> 13;
  h *= 0xc2b2ae35;
  h ^= h >> 16;
  return h;
}

std::uint32_t cryptomatteIdBits(std::uint32_t hash) {
  const std::uint32_t exponent = (hash >> 23) & 255;
  return exponent == 0 || exponent == 255 ? hash ^ (1u << 23) : hash;
}

float cryptomatteId(std::string_view name) {
  return std::bit_cast<float>(cryptomatteIdBits(murmurHash3X86_32(name)));
}

}  // namespace lensrt
