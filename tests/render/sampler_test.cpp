#include "render/sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace lensrt {
namespace {

// The sampler as its header defines it, the slow and plain way: bit loops, the
// Owen scramble as reverse-permute-reverse, Sobol's first two dimensions from
// their generator matrices. The sampler computes the same in the bit-reversed
// domain; it must give the same bits.
std::uint32_t plainReverse(std::uint32_t x) {
  std::uint32_t r = 0;
  for (int i = 0; i < 32; ++i) r |= ((x >> i) & 1u) << (31 - i);
  return r;
}
std::uint32_t plainOwen(std::uint32_t x, std::uint32_t seed) {
  x = plainReverse(x);
  x ^= x * 0x3d20adeau;
  x += seed;
  x *= (seed >> 16) | 1u;
  x ^= x * 0x05526c56u;
  x ^= x * 0x53a22864u;
  return plainReverse(x);
}
std::uint32_t plainSobol(int dimension, std::uint32_t index) {
  std::uint32_t v = 1u << 31, out = 0;
  for (int i = 0; i < 32; ++i) {
    if ((index >> i) & 1u) out ^= dimension == 0 ? (1u << (31 - i)) : v;
    v ^= v >> 1;
  }
  return out;
}
Vec2f plainGet2D(std::uint64_t seed, std::uint64_t pixel, std::uint32_t sample, std::uint32_t dimension) {
  const std::uint32_t dimSeed = hashCombine(hashCombine(hash64(seed), hash64(pixel)), dimension);
  const std::uint32_t index = plainOwen(sample, hashCombine(dimSeed, 0x51ed270bu));
  const std::uint32_t x = plainOwen(plainSobol(0, index), hashCombine(dimSeed, 0x68bc21ebu));
  const std::uint32_t y = plainOwen(plainSobol(1, index), hashCombine(dimSeed, 0x02e5be93u));
  return {float(x >> 8) * 0x1p-24f, float(y >> 8) * 0x1p-24f};
}

TEST(Sampler, IsOwenScrambledSobolPaddedByAnOwenShuffle) {
  std::uint32_t state = 1;
  const auto next = [&] { return state = hashCombine(state, 0x1234567u); };
  for (int n = 0; n < 20000; ++n) {
    const std::uint64_t seed = n % 3 == 0 ? 0 : next(), pixel = next() % 100000;
    // Small indices (the common case) and all 32 bits.
    const std::uint32_t sample = n % 2 ? next() : next() % 1024, dimension = next() % 64;
    const Sampler s(seed, pixel, sample);
    const Vec2f want = plainGet2D(seed, pixel, sample, dimension);
    ASSERT_EQ(s.get2D(dimension), want) << "seed " << seed << " pixel " << pixel << " sample " << sample;
    ASSERT_EQ(s.get1D(dimension), want.x);
  }
}

TEST(Sampler, BlocksAreTheSameBitsAsOneDimensionAtATime) {
  // block() takes the AVX2 lanes on CPUs that have them (blockScalar never):
  // both must equal get2D and get1D dimension by dimension.
  std::uint32_t state = 7;
  const auto next = [&] { return state = hashCombine(state, 0x9abcdefu); };
  for (int n = 0; n < 5000; ++n) {
    const std::uint64_t seed = next(), pixel = next() % 1000000;
    const std::uint32_t sample = n % 2 ? next() : next() % 4096;
    // Near the top of the range too: the dimensions wrap as get2D's do.
    const std::uint32_t first = n % 50 == 0 ? 0xFFFFFFFCu : next() % 64;
    const Sampler s(seed, pixel, sample);
    const SampleBlock fast = s.block(first), plain = s.blockScalar(first);
    for (std::uint32_t k = 0; k < SampleBlock::kDims; ++k) {
      ASSERT_EQ(fast.get2D(k), s.get2D(first + k)) << "dimension " << first + k << " sample " << sample;
      ASSERT_EQ(plain.get2D(k), s.get2D(first + k));
      ASSERT_EQ(fast.get1D(k), s.get1D(first + k));
    }
  }
}

TEST(Sampler, PixelSeedsGiveTheSameBits) {
  // A Sampler made from its pixel's table of seeds must equal one made from
  // (seed, pixel): inside the table, across its end and beyond it.
  std::uint32_t state = 11;
  const auto next = [&] { return state = hashCombine(state, 0x2468aceu); };
  PixelSeeds seeds;
  for (int n = 0; n < 2000; ++n) {
    const std::uint64_t seed = next(), pixel = next() % 1000000;
    const std::uint32_t dimensions = 1 + next() % 40, sample = next() % 1024;
    seeds.reset(seed, pixel, dimensions);  // the same object, reused like the renderer's
    const Sampler plain(seed, pixel, sample), tabled(seeds, sample);
    for (std::uint32_t first = 0; first < seeds.dimensions() + 12; ++first) {
      ASSERT_EQ(tabled.get2D(first), plain.get2D(first)) << "dimension " << first << " of " << dimensions;
      ASSERT_EQ(tabled.get1D(first), plain.get1D(first));
      const SampleBlock a = tabled.block(first), b = plain.blockScalar(first);
      for (std::uint32_t k = 0; k < SampleBlock::kDims; ++k) ASSERT_EQ(a.get2D(k), b.get2D(k));
    }
  }
}

TEST(Sampler, ValuesAreInTheUnitInterval) {
  for (std::uint32_t i = 0; i < 4096; ++i) {
    const Sampler s(7, 12345, i);
    for (std::uint32_t d = 0; d < 20; ++d) {
      const Vec2f u = s.get2D(d);
      EXPECT_GE(u.x, 0.0f);
      EXPECT_LT(u.x, 1.0f);
      EXPECT_GE(u.y, 0.0f);
      EXPECT_LT(u.y, 1.0f);
    }
  }
}

TEST(Sampler, IsAPureFunctionOfSeedPixelSampleAndDimension) {
  const Sampler a(3, 99, 17), b(3, 99, 17);
  for (std::uint32_t d = 0; d < 10; ++d) {
    EXPECT_EQ(a.get2D(d), b.get2D(d));
    EXPECT_EQ(a.get1D(d), b.get2D(d).x);
  }
  // Changing any key changes the values.
  EXPECT_NE(Sampler(4, 99, 17).get2D(0), a.get2D(0));
  EXPECT_NE(Sampler(3, 100, 17).get2D(0), a.get2D(0));
  EXPECT_NE(Sampler(3, 99, 18).get2D(0), a.get2D(0));
  EXPECT_NE(a.get2D(1), a.get2D(0));
}

// The first 2^m samples of every dimension pair form a (0,m,2)-net: each of the
// 2^m elementary intervals of every shape holds exactly one point.
TEST(Sampler, EveryDimensionPairIsStratified) {
  constexpr int kLog2N = 8, kN = 1 << kLog2N;
  for (std::uint64_t pixel : {0ull, 1ull, 77777ull}) {
    for (std::uint32_t d : {0u, 1u, 2u, 9u, 40u}) {
      std::vector<Vec2f> pts;
      for (std::uint32_t i = 0; i < kN; ++i) pts.push_back(Sampler(11, pixel, i).get2D(d));
      for (int bx = 0; bx <= kLog2N; ++bx) {
        const int nx = 1 << bx, ny = kN / nx;
        std::vector<int> counts(kN, 0);
        for (const Vec2f& p : pts) ++counts[int(p.x * nx) * ny + int(p.y * ny)];
        for (int c : counts)
          ASSERT_EQ(c, 1) << "pixel " << pixel << " dim " << d << " shape " << nx << "x" << ny;
      }
    }
  }
}

TEST(Sampler, DimensionsArePaddedNotCorrelated) {
  // Pairing x of one dimension with x of another must not reproduce the
  // diagonal (as unshuffled Sobol dimensions would): Pearson correlation ~ 0.
  constexpr int kN = 4096;
  double sx = 0, sy = 0, sxy = 0, sxx = 0, syy = 0;
  for (std::uint32_t i = 0; i < kN; ++i) {
    const Sampler s(5, 42, i);
    const double x = s.get1D(3), y = s.get1D(4);
    sx += x, sy += y, sxy += x * y, sxx += x * x, syy += y * y;
  }
  const double cov = sxy / kN - (sx / kN) * (sy / kN);
  const double r = cov / std::sqrt((sxx / kN - (sx / kN) * (sx / kN)) * (syy / kN - (sy / kN) * (sy / kN)));
  EXPECT_LT(std::abs(r), 4.0 / std::sqrt(double(kN)));  // 4 sigma of an uncorrelated sample
}

}  // namespace
}  // namespace lensrt
