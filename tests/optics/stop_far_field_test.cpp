// The stop's Fraunhofer far-field table and its sampling: the table against
// the closed forms (the round stop's Airy pattern, the blades' spikes) and
// the sampling against the table by a chi-square test.
#include "optics/stop_far_field.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/constants.h"
#include "split_mix_for_tests.h"

namespace lensrt {
namespace {

// |T(f)|^2 of the unit disc, relative to f = 0: (2 J1(2 pi f) / (2 pi f))^2.
double airy(double f) {
  if (f == 0.0) return 1.0;
  const double v = 2.0 * kPi * f;
  return std::pow(2.0 * std::cyl_bessel_j(1.0, v) / v, 2);
}

TEST(StopFarField, RoundStopIsTheAiryPattern) {
  const StopFarField table;
  const int c = table.size() / 2;
  const double peak = table.at(c, c);
  // The profile along both axes out to 3 cycles per radius.
  double worst = 0.0;
  for (int k = 0; k * table.cellSize() <= 3.0; ++k) {
    const double expected = airy(k * table.cellSize());
    worst = std::max({worst, std::abs(table.at(c + k, c) / peak - expected),
                      std::abs(table.at(c, c - k) / peak - expected)});
  }
  EXPECT_LT(worst, 0.01);
  // The first zero, by linear interpolation of the amplitude, whose sign
  // flips there: 3.8317 / (2 pi) = 0.6098 cycles per radius (1.22 lambda / D).
  int k = 1;
  while (table.at(c + k + 1, c) < table.at(c + k, c)) ++k;
  const double before = std::sqrt(table.at(c + k - 1, c)), at = std::sqrt(table.at(c + k, c)),
               after = std::sqrt(table.at(c + k + 1, c));
  const double zero = before < after ? k - 1 + before / (before + at) : k + at / (at + after);
  EXPECT_NEAR(zero * table.cellSize() / 0.60983, 1.0, 0.02);
  EXPECT_GT(table.capturedLight(), 0.98);
  EXPECT_LE(table.capturedLight(), 1.0 + 1e-12);
}

// A polygon of `blades` edges in the unit circle, its first corner at
// `rotationDeg` from +x.
std::function<double(double, double)> polygon(int blades, double rotationDeg) {
  return [=](double x, double y) {
    for (int k = 0; k < blades; ++k) {
      const double normal = rotationDeg * kPi / 180.0 + (2 * k + 1) * kPi / blades;
      if (x * std::cos(normal) + y * std::sin(normal) > std::cos(kPi / blades)) return 0.0;
    }
    return 1.0;
  };
}

// Spikes along the edges' normals: 6 for 6 blades, 14 for 7 (2-degree bins
// of the table between 5 and 15 cycles per radius; a spike is a bin that is
// the largest within +-8 degrees and above 4 times the median).
TEST(StopFarField, BladesGiveSpikesAlongTheirEdgesNormals) {
  for (const int blades : {6, 7}) {
    const StopFarField table(polygon(blades, 10.0));
    const int c = table.size() / 2;
    std::vector<double> bins(180, 0.0);
    for (int j = 0; j < table.size(); ++j)
      for (int i = 0; i < table.size(); ++i) {
        const double fx = (i - c) * table.cellSize(), fy = (j - c) * table.cellSize(), r = std::hypot(fx, fy);
        if (r < 5.0 || r > 15.0) continue;
        double angle = std::atan2(fy, fx) * 180.0 / kPi;
        if (angle < 0.0) angle += 360.0;
        bins[std::size_t(angle / 2.0) % 180] += table.at(i, j);
      }
    std::vector<double> sorted = bins;
    std::nth_element(sorted.begin(), sorted.begin() + 90, sorted.end());
    std::vector<double> spikes;
    for (int b = 0; b < 180; ++b) {
      bool peak = bins[std::size_t(b)] > 4.0 * sorted[90];
      for (int d = -4; d <= 4 && peak; ++d)
        if (d != 0 && bins[std::size_t((b + d + 180) % 180)] >= bins[std::size_t(b)]) peak = false;
      if (peak) spikes.push_back(2.0 * b + 1.0);
    }
    const int expected = blades % 2 ? 2 * blades : blades;
    ASSERT_EQ(int(spikes.size()), expected) << blades << " blades";
    for (const double angle : spikes) {
      const double period = 360.0 / expected;
      const double phase = std::fmod(angle - 10.0 - 180.0 / blades + 720.0, period);
      EXPECT_LT(std::min(phase, period - phase), 3.0) << blades << " blades, spike at " << angle;
    }
  }
}

// Pearson's chi-square of 400k samples of a 7-blade table against the
// table's own cell sums, in bins of 2 x 2 cells over the central 96 x 96
// cells (where 99% of the samples fall) and one bin for the rest; bins
// expecting fewer than 5 samples are pooled. The Wilson-Hilferty normal
// approximation of the statistic must stay below 4 sigma (a false alarm
// once in 30000 runs; the stream is fixed, so the test is deterministic).
// It fails for a sample placed half a cell off and for the cell chosen
// from the next row's cdf.
TEST(StopFarField, SamplingFollowsTheTable) {
  const StopFarField table(polygon(7, 10.0));
  const int c = table.size() / 2, half = 48, bin = 2, perSide = 2 * half / bin;
  const std::size_t outside = std::size_t(perSide) * std::size_t(perSide);
  const auto binOf = [&](int i, int j) {
    if (std::abs(i - c) >= half || std::abs(j - c) >= half) return outside;
    return std::size_t((j - c + half) / bin) * std::size_t(perSide) + std::size_t((i - c + half) / bin);
  };
  std::vector<double> expected(outside + 1, 0.0), observed(outside + 1, 0.0);
  for (int j = 0; j < table.size(); ++j)
    for (int i = 0; i < table.size(); ++i) expected[binOf(i, j)] += table.at(i, j);
  const int n = 400000;
  test::SplitMix random{7};
  for (int s = 0; s < n; ++s) {
    const StopFarField::Sample x = table.sample({random(), random()});
    const int i = int(std::floor(x.frequency.x / table.cellSize() + 0.5)) + c;
    const int j = int(std::floor(x.frequency.y / table.cellSize() + 0.5)) + c;
    ASSERT_DOUBLE_EQ(x.pdf, table.pdf(x.frequency));
    observed[binOf(i, j)] += 1.0;
  }
  double chi2 = 0.0, pooledE = 0.0, pooledO = 0.0;
  int dof = -1;
  for (std::size_t b = 0; b < expected.size(); ++b) {
    const double e = expected[b] * n;
    if (e < 5.0) {
      pooledE += e, pooledO += observed[b];
      continue;
    }
    chi2 += (observed[b] - e) * (observed[b] - e) / e;
    ++dof;
  }
  if (pooledE > 0.0) chi2 += (pooledO - pooledE) * (pooledO - pooledE) / pooledE, ++dof;
  const double z = (std::cbrt(chi2 / dof) - (1.0 - 2.0 / (9.0 * dof))) / std::sqrt(2.0 / (9.0 * dof));
  EXPECT_GT(dof, 500);
  EXPECT_LT(z, 4.0) << "chi2 " << chi2 << " with " << dof << " degrees of freedom";
}

}  // namespace
}  // namespace lensrt
