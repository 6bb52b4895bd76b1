// Glass index models against published catalogue values and closed forms.
#include "optics/glass.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "optics/lens_system.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

// Schott N-BK7: Sellmeier coefficients and the indices printed on its data
// sheet (n_F = 1.52238, n_C = 1.51432, n_g = 1.52668, n_d = 1.51680).
Medium nbk7() {
  Medium m;
  m.nd = 1.5168;
  m.vd = 64.17;
  m.glass = "N-BK7";
  m.sellmeier = Sellmeier{{1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}};
  return m;
}

TEST(Glass, SellmeierMatchesTheDataSheet) {
  const Dispersion d = Dispersion::of(nbk7());
  ASSERT_TRUE(d.sellmeier);
  EXPECT_DOUBLE_EQ(d.index(kWavelengthDNm), 1.5168);
  EXPECT_NEAR(d.index(kWavelengthFNm), 1.52238, 2e-5);
  EXPECT_NEAR(d.index(kWavelengthCNm), 1.51432, 2e-5);
  EXPECT_NEAR(d.index(435.8343), 1.52668, 2e-5);
  // The formula itself, written out here: n^2 = 1 + sum B l^2 / (l^2 - C).
  const double l2 = 0.5461 * 0.5461;  // e line, um^2
  const double n = std::sqrt(1.0 + 1.03961212 * l2 / (l2 - 0.00600069867) +
                             0.231792344 * l2 / (l2 - 0.0200179144) + 1.01046945 * l2 / (l2 - 103.560653));
  EXPECT_NEAR(d.index(546.1), n + (1.5168 - nbk7().sellmeier->index(kWavelengthDNm)), 1e-12);
}

TEST(Glass, SellmeierTakesPrecedenceOverTheAbbeNumber) {
  Medium m = nbk7();
  m.vd = 30.0;  // a wrong Abbe number must not matter when Sellmeier data is there
  EXPECT_NEAR(Dispersion::of(m).index(kWavelengthFNm), 1.52238, 2e-5);
  m.sellmeier.reset();
  EXPECT_NEAR(Dispersion::of(m).index(kWavelengthFNm) - Dispersion::of(m).index(kWavelengthCNm),
              0.5168 / 30.0, 1e-12);
}

TEST(Glass, CauchyAndSellmeierAgreeRoughlyForACrown) {
  Medium cauchy = nbk7();
  cauchy.sellmeier.reset();
  for (double l = 420.0; l <= 680.0; l += 20.0)
    EXPECT_NEAR(Dispersion::of(cauchy).index(l), Dispersion::of(nbk7()).index(l), 1e-3) << l;
}

TEST(Glass, DLineTraceIsTheSameWithOrWithoutSellmeier) {
  LensPrescription plain = test::singlet(60.0, -80.0, 5.0, 1.5168);
  plain.surfaces[1].medium.vd = 64.17;
  LensPrescription sell = plain;
  sell.surfaces[1].medium = nbk7();
  const LensSystem a(plain), b(sell);
  const LensRay ray{{3.0, 1.0, -20.0}, {0.01, 0.0, 1.0}};
  const auto ra = a.traceFromScene(ray, kWavelengthDNm), rb = b.traceFromScene(ray, kWavelengthDNm);
  ASSERT_TRUE(ra && rb);
  EXPECT_EQ(ra->origin.x, rb->origin.x);
  EXPECT_EQ(ra->direction.x, rb->direction.x);
  // Away from the d line the glasses differ only by the model (< 1e-3 in n).
  const auto fa = a.traceFromScene(ray, 450.0), fb = b.traceFromScene(ray, 450.0);
  ASSERT_TRUE(fa && fb);
  EXPECT_NE(fa->direction.x, fb->direction.x);
}

TEST(Glass, ValidationRefusesAPoleInTheVisible) {
  LensPrescription rx = test::singlet(60.0, -80.0, 5.0, 1.5168);
  rx.surfaces[1].medium = nbk7();
  EXPECT_NO_THROW(validatePrescription(rx));
  rx.surfaces[1].medium.sellmeier->c[1] = 0.25;  // pole at 500 nm
  EXPECT_THROW(validatePrescription(rx), InputError);
  rx.surfaces[1].medium.sellmeier->c[1] = 0.02;
  rx.surfaces[1].medium.sellmeier->b[0] = NAN;
  EXPECT_THROW(validatePrescription(rx), InputError);
}

}  // namespace
}  // namespace lensrt
