#include "render/sampler.h"

#include <array>

#include "core/cpu_features.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define LENSRT_SAMPLER_AVX2 1
#endif

namespace lensrt {
namespace {

std::uint32_t reverseBits(std::uint32_t x) {
#if defined(__clang__)
  return __builtin_bitreverse32(x);
#else
#if defined(__GNUC__)
  x = __builtin_bswap32(x);  // the bytes in reverse order, then the bits within each byte
#else
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  x = (x >> 16) | (x << 16);
#endif
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
#endif
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

// A nested uniform (Owen) scramble of x is reverseBits(laineKarras(reverseBits(x), seed)).
// The sampler keeps the shuffled sample index in the bit-reversed domain, where its
// scramble is laineKarras alone: the sample index is reversed once per Sampler,
// and the first Sobol dimension of the shuffled index (van der Corput: the index
// reversed) is that reversed index itself; only what enters a point's scramble and
// the values handed out are reversed. Three reversals per 2D point instead of seven.

// The second Sobol dimension (the Pascal matrix) from and to the reversed domain:
// reverseBits(sobol1(reverseBits(r))), a linear map applied a byte of r at a time:
// table[k][b] is the XOR of the columns that byte b of r at byte position k selects.
using SobolTable = std::array<std::array<std::uint32_t, 256>, 4>;
constexpr std::uint32_t reverseBitsConstexpr(std::uint32_t x) {
  std::uint32_t r = 0;
  for (int i = 0; i < 32; ++i) r |= ((x >> i) & 1u) << (31 - i);
  return r;
}
constexpr SobolTable makeReversedSobol1Table() {
  // direction[i]: the generator matrix's column for bit i of the index.
  std::array<std::uint32_t, 32> direction{};
  std::uint32_t v = 1u << 31;
  for (int i = 0; i < 32; ++i, v ^= v >> 1) direction[i] = v;
  SobolTable t{};
  // Bit j of r is bit 31 - j of the index; the result is reversed too.
  for (int k = 0; k < 4; ++k)
    for (int b = 0; b < 256; ++b)
      for (int i = 0; i < 8; ++i)
        if (b & (1 << i)) t[k][b] ^= reverseBitsConstexpr(direction[31 - (8 * k + i)]);
  return t;
}
constexpr SobolTable kReversedSobol1 = makeReversedSobol1Table();

std::uint32_t reversedSobol1(std::uint32_t r) {
  return kReversedSobol1[0][r & 0xff] ^ kReversedSobol1[1][(r >> 8) & 0xff] ^
         kReversedSobol1[2][(r >> 16) & 0xff] ^ kReversedSobol1[3][r >> 24];
}

float toUnitFloat(std::uint32_t x) {
  // 24 high bits: exactly representable, strictly below 1.
  return float(x >> 8) * 0x1p-24f;
}

#if LENSRT_SAMPLER_AVX2
// The sampler's integer steps on eight dimensions at once (GCC vector
// extensions in AVX2 registers): the same operations lane by lane, so the
// same bits as the scalar code.
#define LENSRT_AVX2 __attribute__((target("avx2")))
using U8 = std::uint32_t __attribute__((vector_size(32)));

LENSRT_AVX2 inline U8 splat(std::uint32_t v) {
  return U8{} + v;
}
LENSRT_AVX2 inline U8 hashCombine8(U8 seed, U8 v) {
  U8 x = seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2));
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}
LENSRT_AVX2 inline U8 laineKarras8(U8 x, U8 seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return x;
}
LENSRT_AVX2 inline U8 reverseBits8(U8 x) {
  // The bytes of each lane in reverse order, then the bits within each byte.
  const __m256i byteSwap = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,  //
                                            3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  x = (U8)_mm256_shuffle_epi8((__m256i)x, byteSwap);
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  return ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
}
LENSRT_AVX2 inline U8 reversedSobol1x8(U8 r) {
  U8 out{};
  for (int k = 0; k < 4; ++k) {
    const __m256i byte = (__m256i)((r >> (8 * k)) & 0xffu);
    out ^= (U8)_mm256_i32gather_epi32(reinterpret_cast<const int*>(kReversedSobol1[k].data()), byte, 4);
  }
  return out;
}
LENSRT_AVX2 inline void storeUnitFloats(float* out, U8 x) {
  _mm256_storeu_ps(out, _mm256_mul_ps(_mm256_cvtepi32_ps((__m256i)(x >> 8)), _mm256_set1_ps(0x1p-24f)));
}

// Sampler::get2D on dimensions first .. first + 7 (see there).
LENSRT_AVX2 void block8(std::uint32_t pixelSeed, std::uint32_t reversedIndex, std::uint32_t first, float* xs,
                        float* ys) {
  const U8 dimSeed = hashCombine8(splat(pixelSeed), U8{0, 1, 2, 3, 4, 5, 6, 7} + first);
  const U8 r = laineKarras8(splat(reversedIndex), hashCombine8(dimSeed, splat(0x51ed270bu)));
  storeUnitFloats(xs, reverseBits8(laineKarras8(reverseBits8(r), hashCombine8(dimSeed, splat(0x68bc21ebu)))));
  storeUnitFloats(ys,
                  reverseBits8(laineKarras8(reversedSobol1x8(r), hashCombine8(dimSeed, splat(0x02e5be93u)))));
}
static_assert(SampleBlock::kDims == 8);
#endif

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
    : pixelSeed_(hashCombine(hash64(seed), hash64(pixelIndex))), reversedIndex_(reverseBits(sampleIndex)) {}

// Per dimension the sample index is shuffled by an Owen scramble (padding), then
// the point of the shuffled index is Owen scrambled per coordinate (see above):
// r is the shuffled index reversed, which is also the point's x before its scramble.
float Sampler::get1D(std::uint32_t dimension) const {
  // The x coordinate of get2D(dimension), without computing y.
  const std::uint32_t dimSeed = hashCombine(pixelSeed_, dimension);
  const std::uint32_t r = laineKarras(reversedIndex_, hashCombine(dimSeed, 0x51ed270bu));
  return toUnitFloat(reverseBits(laineKarras(reverseBits(r), hashCombine(dimSeed, 0x68bc21ebu))));
}

Vec2f Sampler::get2D(std::uint32_t dimension) const {
  const std::uint32_t dimSeed = hashCombine(pixelSeed_, dimension);
  const std::uint32_t r = laineKarras(reversedIndex_, hashCombine(dimSeed, 0x51ed270bu));
  const std::uint32_t x = reverseBits(laineKarras(reverseBits(r), hashCombine(dimSeed, 0x68bc21ebu)));
  const std::uint32_t y = reverseBits(laineKarras(reversedSobol1(r), hashCombine(dimSeed, 0x02e5be93u)));
  return {toUnitFloat(x), toUnitFloat(y)};
}

SampleBlock Sampler::blockScalar(std::uint32_t first) const {
  SampleBlock b;
  for (std::uint32_t k = 0; k < SampleBlock::kDims; ++k) {
    const Vec2f p = get2D(first + k);
    b.x_[k] = p.x;
    b.y_[k] = p.y;
  }
  return b;
}

SampleBlock Sampler::block(std::uint32_t first) const {
#if LENSRT_SAMPLER_AVX2
  if (avx2Enabled()) {
    SampleBlock b;
    block8(pixelSeed_, reversedIndex_, first, b.x_.data(), b.y_.data());
    return b;
  }
#endif
  return blockScalar(first);
}

}  // namespace lensrt
