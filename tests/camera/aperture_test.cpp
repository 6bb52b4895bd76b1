// Aperture sampling: uniform over the shape (chi-square), always inside it,
// with the area of the nominal f-number's disk.
#include "camera/aperture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/constants.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

// Chi-square over a grid of cells on [-R, R]^2: expected counts from the
// fraction of each cell inside the shape (by `contains` on a fine subgrid).
// Returns the statistic and the degrees of freedom.
std::pair<double, int> chiSquare(const Aperture& ap, int samples) {
  constexpr int kCells = 12, kSub = 24;
  const double r = ap.circumradius() * 1.0001;
  std::vector<double> observed(kCells * kCells, 0.0), expected(kCells * kCells, 0.0);
  double insideTotal = 0;
  for (int j = 0; j < kCells * kSub; ++j)
    for (int i = 0; i < kCells * kSub; ++i) {
      const Vec2d p{-r + 2 * r * (i + 0.5) / (kCells * kSub), -r + 2 * r * (j + 0.5) / (kCells * kSub)};
      if (ap.contains(p)) {
        expected[(j / kSub) * kCells + i / kSub] += 1;
        insideTotal += 1;
      }
    }
  SplitMix64 rng(42);
  for (int k = 0; k < samples; ++k) {
    const Vec2d p = ap.sample({rng.uniform(), rng.uniform()});
    const int i = std::clamp(int((p.x + r) / (2 * r) * kCells), 0, kCells - 1);
    const int j = std::clamp(int((p.y + r) / (2 * r) * kCells), 0, kCells - 1);
    observed[j * kCells + i] += 1;
  }
  double chi2 = 0;
  int dof = -1;
  double pooledObs = 0, pooledExp = 0;
  for (std::size_t c = 0; c < observed.size(); ++c) {
    const double e = expected[c] / insideTotal * samples;
    if (e < 5) {  // pool sparse edge cells, as usual for chi-square
      pooledObs += observed[c];
      pooledExp += e;
      continue;
    }
    chi2 += (observed[c] - e) * (observed[c] - e) / e;
    ++dof;
  }
  if (pooledExp >= 5) {
    chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
    ++dof;
  }
  return {chi2, dof};
}

// Upper 0.1% point of chi-square (Wilson-Hilferty).
double chi2Critical(int dof) {
  const double z = 3.09, k = dof;
  return k * std::pow(1 - 2 / (9 * k) + z * std::sqrt(2 / (9 * k)), 3);
}

TEST(Aperture, SamplesAreUniformOverTheShape) {
  for (const int blades : {0, 3, 5, 6, 9})
    for (const double rotation : {0.0, 17.0}) {
      const Aperture ap(2.0, {blades, rotation});
      const auto [chi2, dof] = chiSquare(ap, 200000);
      ASSERT_GT(dof, 30);
      // Edge cells' expected counts come from a subgrid, good to about 0.2%;
      // far below the statistical noise at this sample count.
      EXPECT_LT(chi2, chi2Critical(dof)) << blades << " blades, rotation " << rotation;
    }
}

TEST(Aperture, SamplesStayInsideAndReachTheCorners) {
  for (const int blades : {0, 3, 5, 8}) {
    const Aperture ap(1.5, {blades, 30.0});
    SplitMix64 rng(5);
    double farthest = 0;
    for (int k = 0; k < 100000; ++k) {
      const Vec2d p = ap.sample({rng.uniform(), rng.uniform()});
      ASSERT_TRUE(ap.contains(p)) << blades << " blades: " << p.x << ", " << p.y;
      farthest = std::max(farthest, std::hypot(p.x, p.y));
    }
    EXPECT_GT(farthest, 0.97 * ap.circumradius());
  }
}

TEST(Aperture, PolygonHasTheDiskAreaAndItsCornersWhereRotated) {
  for (const int blades : {3, 5, 6, 12}) {
    const double radius = 1.0, rotation = 25.0;
    const Aperture ap(radius, {blades, rotation});
    // Area by counting grid points inside.
    const int n = 1000;
    const double r = ap.circumradius();
    int inside = 0;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        inside += ap.contains({-r + 2 * r * (i + 0.5) / n, -r + 2 * r * (j + 0.5) / n});
    EXPECT_NEAR(inside * 4 * r * r / (double(n) * n), kPi * radius * radius, 0.003);
    // Regular n-gon of area pi: circumradius sqrt(2 pi / (n sin(2 pi / n))).
    EXPECT_NEAR(r, std::sqrt(2 * kPi / (blades * std::sin(2 * kPi / blades))), 1e-12);
    const double a = rotation * kPi / 180;
    EXPECT_TRUE(ap.contains({0.999 * r * std::cos(a), 0.999 * r * std::sin(a)}));
    EXPECT_FALSE(ap.contains({1.001 * r * std::cos(a), 1.001 * r * std::sin(a)}));
    // Halfway between two corners lies an edge, at the inradius r cos(pi / n).
    const double mid = a + kPi / blades, inr = r * std::cos(kPi / blades);
    EXPECT_TRUE(ap.contains({0.999 * inr * std::cos(mid), 0.999 * inr * std::sin(mid)}));
    EXPECT_FALSE(ap.contains({1.001 * inr * std::cos(mid), 1.001 * inr * std::sin(mid)}));
  }
}

TEST(Aperture, RejectsBadShapes) {
  EXPECT_THROW(Aperture(1.0, {2, 0.0}), std::invalid_argument);
  EXPECT_THROW(Aperture(0.0, {0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace lensrt
