#include "render/sampler.h"

#include <gtest/gtest.h>

#include <set>
#include <vector>

namespace lensrt {
namespace {

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
