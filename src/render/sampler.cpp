#include "render/sampler.h"

#include <array>
#include <cstring>

#include "core/cpu_features.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define LENSRT_SAMPLER_AVX2 1
#endif

namespace lensrt {
namespace {

// The sampler's integer steps, written once for one value (std::uint32_t) and
// for eight AVX2 lanes (U8 below): the same operations lane by lane, so the
// same bits. In place and by reference (a vector passed by value outside AVX
// code would change the ABI), always inlined.

// A strong 32-bit mixer (lowbias32, C. Wellons) over seed and value.
template <class T>
[[gnu::always_inline]] inline void hashCombineInto(T& x, const T& seed, const T& v) {
  x = seed ^ (v + 0x9e3779b9u + (seed << 6) + (seed >> 2));
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
}

// Laine-Karras style permutation: each bit only depends on lower bits, so after
// bit reversal it is a nested uniform (Owen) scramble. Constants from Burley 2020
// with the improved mixing by N. Vegdahl.
template <class T>
[[gnu::always_inline]] inline void laineKarrasInPlace(T& x, const T& seed) {
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
}

// The bits of each byte in reverse order (a bit reversal after a byte swap).
template <class T>
[[gnu::always_inline]] inline void reverseBitsInBytes(T& x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
}

// The second Sobol dimension of index i, bit reversed: reverseBits(sobol1(i)).
// Its generator columns are v_k = 2^31 (1 + x)^k over GF(2), x a right shift,
// so by Lucas' theorem bit 31 - m of sobol1(i) is the XOR of the bits k of i
// whose bit set contains m's: a superset-XOR transform over the bit
// positions, five shift-and-mask steps (no table, so SIMD lanes need no gather).
template <class T>
[[gnu::always_inline]] inline void sobol1ReversedInPlace(T& i) {
  i ^= (i >> 1) & 0x55555555u;
  i ^= (i >> 2) & 0x33333333u;
  i ^= (i >> 4) & 0x0F0F0F0Fu;
  i ^= (i >> 8) & 0x00FF00FFu;
  i ^= (i >> 16) & 0x0000FFFFu;
}

std::uint32_t reverseBits(std::uint32_t x) {
#if defined(__clang__)
  return __builtin_bitreverse32(x);
#else
#if defined(__GNUC__)
  x = __builtin_bswap32(x);
#else
  x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
  x = (x >> 16) | (x << 16);
#endif
  reverseBitsInBytes(x);
  return x;
#endif
}

std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
  laineKarrasInPlace(x, seed);
  return x;
}

std::uint32_t sobol1Reversed(std::uint32_t i) {
  sobol1ReversedInPlace(i);
  return i;
}

// A nested uniform (Owen) scramble of x is reverseBits(laineKarras(reverseBits(x), seed)).
// The sampler keeps the shuffled sample index in the bit-reversed domain, where its
// scramble is laineKarras alone: the sample index is reversed once per Sampler,
// and the first Sobol dimension of the shuffled index (van der Corput: the index
// reversed) is that reversed index itself; only what enters a point's scramble and
// the values handed out are reversed. Three reversals per 2D point instead of seven.

float toUnitFloat(std::uint32_t x) {
  // 24 high bits: exactly representable, strictly below 1.
  return float(x >> 8) * 0x1p-24f;
}

// A dimension's three scramble seeds are its seed hashed with these.
constexpr std::uint32_t kShuffleSalt = 0x51ed270bu, kXSalt = 0x68bc21ebu, kYSalt = 0x02e5be93u;

DimensionSeeds hashSeeds(std::uint32_t pixelSeed, std::uint32_t dimension) {
  const std::uint32_t dimSeed = hashCombine(pixelSeed, dimension);
  return {hashCombine(dimSeed, kShuffleSalt), hashCombine(dimSeed, kXSalt), hashCombine(dimSeed, kYSalt)};
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
  U8 x;
  hashCombineInto(x, seed, v);
  return x;
}
LENSRT_AVX2 inline U8 laineKarras8(U8 x, U8 seed) {
  laineKarrasInPlace(x, seed);
  return x;
}
LENSRT_AVX2 inline U8 reverseBits8(U8 x) {
  // The bytes of each lane in reverse order, then the bits within each byte.
  const __m256i byteSwap = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,  //
                                            3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  x = (U8)_mm256_shuffle_epi8((__m256i)x, byteSwap);
  reverseBitsInBytes(x);
  return x;
}
LENSRT_AVX2 inline U8 sobol1Reversed8(U8 i) {
  sobol1ReversedInPlace(i);
  return i;
}
LENSRT_AVX2 inline void storeUnitFloats(float* out, U8 x) {
  _mm256_storeu_ps(out, _mm256_mul_ps(_mm256_cvtepi32_ps((__m256i)(x >> 8)), _mm256_set1_ps(0x1p-24f)));
}

LENSRT_AVX2 inline U8 load8(const std::uint32_t* p) {
  U8 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
LENSRT_AVX2 inline void store8(std::uint32_t* p, U8 v) {
  std::memcpy(p, &v, sizeof v);
}

// The seeds of dimensions first .. first + 7 (see PixelSeeds::reset).
LENSRT_AVX2 void seeds8(std::uint32_t pixelSeed, std::uint32_t first, std::uint32_t* shuffle,
                        std::uint32_t* x, std::uint32_t* y) {
  const U8 dimSeed = hashCombine8(splat(pixelSeed), U8{0, 1, 2, 3, 4, 5, 6, 7} + first);
  store8(shuffle, hashCombine8(dimSeed, splat(kShuffleSalt)));
  store8(x, hashCombine8(dimSeed, splat(kXSalt)));
  store8(y, hashCombine8(dimSeed, splat(kYSalt)));
}

// Sampler::get2D on eight dimensions with these seeds (see there).
LENSRT_AVX2 void points8(U8 shuffle, U8 xSeed, U8 ySeed, std::uint32_t reversedIndex, float* xs, float* ys) {
  const U8 index = reverseBits8(laineKarras8(splat(reversedIndex), shuffle));
  storeUnitFloats(xs, reverseBits8(laineKarras8(index, xSeed)));
  storeUnitFloats(ys, reverseBits8(laineKarras8(sobol1Reversed8(index), ySeed)));
}

// Dimensions first .. first + 7 from a pixel's table of seeds.
LENSRT_AVX2 void block8(const std::uint32_t* shuffle, const std::uint32_t* x, const std::uint32_t* y,
                        std::uint32_t reversedIndex, float* xs, float* ys) {
  points8(load8(shuffle), load8(x), load8(y), reversedIndex, xs, ys);
}

// The same from the pixel seed (dimensions beyond a pixel's table).
LENSRT_AVX2 void block8(std::uint32_t pixelSeed, std::uint32_t reversedIndex, std::uint32_t first, float* xs,
                        float* ys) {
  std::array<std::uint32_t, 8> shuffle, x, y;
  seeds8(pixelSeed, first, shuffle.data(), x.data(), y.data());
  block8(shuffle.data(), x.data(), y.data(), reversedIndex, xs, ys);
}

static_assert(SampleBlock::kDims == 8);
#endif

}  // namespace

std::uint32_t hashCombine(std::uint32_t seed, std::uint32_t v) {
  std::uint32_t x;
  hashCombineInto(x, seed, v);
  return x;
}

std::uint32_t hash64(std::uint64_t v) {
  return hashCombine(hashCombine(0x2545f491u, std::uint32_t(v)), std::uint32_t(v >> 32));
}

namespace {
std::uint32_t pixelSeedOf(std::uint64_t seed, std::uint64_t pixelIndex) {
  return hashCombine(hash64(seed), hash64(pixelIndex));
}
}  // namespace

void PixelSeeds::reset(std::uint64_t seed, std::uint64_t pixelIndex, std::uint32_t dimensions) {
  pixelSeed_ = pixelSeedOf(seed, pixelIndex);
  // Whole blocks of eight, so the SIMD path fills them directly.
  const std::uint32_t n = (dimensions + 7) / 8 * 8;
  shuffle_.resize(n);
  xSeed_.resize(n);
  ySeed_.resize(n);
#if LENSRT_SAMPLER_AVX2
  if (avx2Enabled()) {
    for (std::uint32_t d = 0; d < n; d += 8) seeds8(pixelSeed_, d, &shuffle_[d], &xSeed_[d], &ySeed_[d]);
    return;
  }
#endif
  for (std::uint32_t d = 0; d < n; ++d) {
    const DimensionSeeds h = hashSeeds(pixelSeed_, d);
    shuffle_[d] = h.shuffle;
    xSeed_[d] = h.x;
    ySeed_[d] = h.y;
  }
}

Sampler::Sampler(std::uint64_t seed, std::uint64_t pixelIndex, std::uint32_t sampleIndex)
    : pixelSeed_(pixelSeedOf(seed, pixelIndex)), reversedIndex_(reverseBits(sampleIndex)) {}

Sampler::Sampler(const PixelSeeds& seeds, std::uint32_t sampleIndex)
    : pixelSeed_(seeds.pixelSeed()), reversedIndex_(reverseBits(sampleIndex)), seeds_(&seeds) {}

// From the pixel's table when it has the dimension.
DimensionSeeds Sampler::seeds(std::uint32_t dimension) const {
  if (seeds_ && dimension < seeds_->dimensions())
    return {seeds_->shuffle_[dimension], seeds_->xSeed_[dimension], seeds_->ySeed_[dimension]};
  return hashSeeds(pixelSeed_, dimension);
}

// Per dimension the sample index is shuffled by an Owen scramble (padding),
// then the point of the shuffled index is Owen scrambled per coordinate (see
// above): `index` is the shuffled index, which reversed is the point's x
// before its scramble (van der Corput), so x's scramble is laineKarras(index).
float Sampler::get1D(std::uint32_t dimension) const {
  // The x coordinate of get2D(dimension), without computing y.
  const DimensionSeeds s = seeds(dimension);
  const std::uint32_t index = reverseBits(laineKarras(reversedIndex_, s.shuffle));
  return toUnitFloat(reverseBits(laineKarras(index, s.x)));
}

Vec2f Sampler::get2D(std::uint32_t dimension) const {
  const DimensionSeeds s = seeds(dimension);
  const std::uint32_t index = reverseBits(laineKarras(reversedIndex_, s.shuffle));
  const std::uint32_t x = reverseBits(laineKarras(index, s.x));
  const std::uint32_t y = reverseBits(laineKarras(sobol1Reversed(index), s.y));
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
    // Dimensions past the pixel's table (deep paths) hash their seeds here.
    if (seeds_ && first < seeds_->dimensions() && seeds_->dimensions() - first >= SampleBlock::kDims)
      block8(&seeds_->shuffle_[first], &seeds_->xSeed_[first], &seeds_->ySeed_[first], reversedIndex_,
             b.x_.data(), b.y_.data());
    else
      block8(pixelSeed_, reversedIndex_, first, b.x_.data(), b.y_.data());
    return b;
  }
#endif
  return blockScalar(first);
}

}  // namespace lensrt
