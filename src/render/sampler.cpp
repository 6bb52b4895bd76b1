#include "render/sampler.h"

#include <array>

namespace lensrt {
namespace {

std::uint32_t reverseBits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  return (x >> 16) | (x << 16);
}

// Laine-Karras style permutation: each bit only depends on lower bits, so after
// bit reversal it is a nested uniform (Owen) scramble. Constants from Burley 2020
// with the improved mixing by N. Vegdahl.
std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}

std::uint32_t owenScramble(std::uint32_t x, std::uint32_t seed) {
  return reverseBits(laineKarras(reverseBits(x), seed));
}

// The first two Sobol dimensions: van der Corput (identity matrix, bit reversed)
// and the Pascal-matrix dimension.
std::uint32_t sobol0(std::uint32_t index) {
  return reverseBits(index);
}
// The generator matrix applied a byte at a time: table[k][b] is the XOR of the
// direction numbers selected by byte b of the index at byte position k (the
// shuffled indices use all 32 bits, so a bit loop would run 32 times).
using SobolTable = std::array<std::array<std::uint32_t, 256>, 4>;
constexpr SobolTable makeSobol1Table() {
  std::array<std::uint32_t, 32> direction{};
  std::uint32_t v = 1u << 31;
  for (int i = 0; i < 32; ++i, v ^= v >> 1) direction[i] = v;
  SobolTable t{};
  for (int k = 0; k < 4; ++k)
    for (int b = 0; b < 256; ++b)
      for (int i = 0; i < 8; ++i)
        if (b & (1 << i)) t[k][b] ^= direction[8 * k + i];
  return t;
}
constexpr SobolTable kSobol1 = makeSobol1Table();

std::uint32_t sobol1(std::uint32_t index) {
  return kSobol1[0][index & 0xff] ^ kSobol1[1][(index >> 8) & 0xff] ^ kSobol1[2][(index >> 16) & 0xff] ^
         kSobol1[3][index >> 24];
}

float toUnitFloat(std::uint32_t x) {
  // 24 high bits: exactly representable, strictly below 1.
  return float(x >> 8) * 0x1p-24f;
}

}  // namespace

std::uint32_t hashCombine(std::uint32_t seed, std::uint32_t v) {
  // A strong 32-bit mixer (lowbias32, C. Wellons) over seed and value.
  std::uint32_t x = seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2));
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

std::uint32_t hash64(std::uint64_t v) {
  return hashCombine(hashCombine(0x2545f491u, std::uint32_t(v)), std::uint32_t(v >> 32));
}

Sampler::Sampler(std::uint64_t seed, std::uint64_t pixelIndex, std::uint32_t sampleIndex)
    : pixelSeed_(hashCombine(hash64(seed), hash64(pixelIndex))), sampleIndex_(sampleIndex) {}

float Sampler::get1D(std::uint32_t dimension) const {
  // The x coordinate of get2D(dimension), without computing y.
  const std::uint32_t dimSeed = hashCombine(pixelSeed_, dimension);
  const std::uint32_t index = owenScramble(sampleIndex_, hashCombine(dimSeed, 0x51ed270bu));
  return toUnitFloat(owenScramble(sobol0(index), hashCombine(dimSeed, 0x68bc21ebu)));
}

Vec2f Sampler::get2D(std::uint32_t dimension) const {
  const std::uint32_t dimSeed = hashCombine(pixelSeed_, dimension);
  const std::uint32_t index = owenScramble(sampleIndex_, hashCombine(dimSeed, 0x51ed270bu));
  const std::uint32_t x = owenScramble(sobol0(index), hashCombine(dimSeed, 0x68bc21ebu));
  const std::uint32_t y = owenScramble(sobol1(index), hashCombine(dimSeed, 0x02e5be93u));
  return {toUnitFloat(x), toUnitFloat(y)};
}

}  // namespace lensrt
