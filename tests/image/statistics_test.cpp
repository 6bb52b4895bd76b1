#include "image/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace lensrt {
namespace {

TEST(Statistics, NormalTailKnownQuantiles) {
  EXPECT_NEAR(normalUpperTail(0.0), 0.5, 1e-15);
  EXPECT_NEAR(normalUpperTail(1.959963984540054), 0.025, 1e-12);
  EXPECT_NEAR(normalUpperTail(-1.0), 0.8413447460685429, 1e-12);
}

TEST(Statistics, StudentTMatchesClosedFormsForOneAndTwoDegrees) {
  for (const double t : {-3.0, -0.5, 0.0, 0.7, 2.0, 12.7, 100.0}) {
    // nu = 1 is the Cauchy distribution.
    EXPECT_NEAR(studentTUpperTail(t, 1), 0.5 - std::atan(t) / std::numbers::pi, 1e-12) << t;
    EXPECT_NEAR(studentTUpperTail(t, 2), 0.5 * (1 - t / std::sqrt(2 + t * t)), 1e-12) << t;
  }
}

TEST(Statistics, StudentTApproachesNormalForManyDegrees) {
  EXPECT_NEAR(studentTUpperTail(2.5, 1e7), normalUpperTail(2.5), 1e-8);
}

TEST(Statistics, IncompleteBetaClosedForms) {
  // I_x(1, b) = 1 - (1-x)^b and I_x(a, 1) = x^a.
  EXPECT_NEAR(incompleteBeta(1, 3, 0.2), 1 - std::pow(0.8, 3), 1e-14);
  EXPECT_NEAR(incompleteBeta(2.5, 1, 0.7), std::pow(0.7, 2.5), 1e-14);
  EXPECT_EQ(incompleteBeta(2, 3, 0), 0.0);
  EXPECT_EQ(incompleteBeta(2, 3, 1), 1.0);
}

TEST(Statistics, CriticalValuesInvertTheTails) {
  EXPECT_NEAR(twoSidedCriticalValue(0.05, 0), 1.959963984540054, 1e-9);
  // Cauchy: P(|T| > c) = 1 - 2 atan(c) / pi.
  EXPECT_NEAR(twoSidedCriticalValue(0.05, 1), std::tan(std::numbers::pi * 0.95 / 2), 1e-8);
  const double c = twoSidedCriticalValue(1e-5, 15);
  EXPECT_NEAR(2 * studentTUpperTail(c, 15), 1e-5, 1e-12);
}

TEST(Statistics, BinomialCriticalCountByHand) {
  // Binomial(10, 1/2): P(X >= 8) = 56/1024 > 0.05, P(X >= 9) = 11/1024 <= 0.05.
  EXPECT_EQ(binomialCriticalCount(10, 0.5, 0.05), 8);
  // P(X >= 10) = 1/1024 <= 0.01 but P(X >= 9) = 11/1024 > 0.01.
  EXPECT_EQ(binomialCriticalCount(10, 0.5, 0.01), 9);
  EXPECT_EQ(binomialCriticalCount(1000, 0.0, 0.001), 0);
  EXPECT_EQ(binomialCriticalCount(0, 0.1, 0.001), 0);
  // Binomial(3, 0.1): P(X > 0) = 0.271, P(X > 1) = 0.028, P(X > 2) = 0.001.
  EXPECT_EQ(binomialCriticalCount(3, 0.1, 0.03), 1);
  EXPECT_EQ(binomialCriticalCount(3, 0.1, 0.002), 2);
}

}  // namespace
}  // namespace lensrt
