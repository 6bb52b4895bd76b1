// Chromatic aberration of the seed's double Gauss against a paraxial
// calculation written here from the lecture's table, with its own dispersion
// model (two-term Cauchy through n_d with n_F - n_C = (n_d - 1) / V_d).
#include "optics/chromatic.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "optics/distortion.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

// The lecture's table: radius (0: the stop), thickness, n_d, V_d (1, 0: air).
constexpr std::array<std::array<double, 4>, 11> kSeedDoubleGauss{{
    {58.950, 7.520, 1.670, 47.1},
    {169.660, 0.240, 1, 0},
    {38.550, 8.050, 1.670, 47.1},
    {81.540, 6.550, 1.699, 30.1},
    {25.500, 11.410, 1, 0},
    {0, 9.000, 1, 0},
    {-28.990, 2.360, 1.603, 38.0},
    {81.540, 12.130, 1.658, 57.3},
    {-40.770, 0.380, 1, 0},
    {874.130, 6.440, 1.717, 48.0},
    {-79.460, 72.228, 1, 0},
}};

// n(l) = A + B / l^2 through (l_d, n_d) with n(l_F) - n(l_C) = (n_d - 1) / V_d.
double cauchy(double nd, double vd, double wl) {
  if (vd == 0.0) return nd;
  const double b = (nd - 1.0) / vd / (1.0 / (486.1327 * 486.1327) - 1.0 / (656.2725 * 656.2725));
  return nd + b * (1.0 / (wl * wl) - 1.0 / (587.5618 * 587.5618));
}

// Back focal length: a ray parallel to the axis at height 1, y-nu trace.
double backFocalLength(double wl) {
  double y = 1.0, nu = 0.0, n = 1.0;
  for (std::size_t i = 0; i < kSeedDoubleGauss.size(); ++i) {
    const auto& row = kSeedDoubleGauss[i];
    const double n2 = cauchy(row[2], row[3], wl);
    const double c = row[0] == 0.0 ? 0.0 : 1.0 / row[0];
    nu -= y * c * (n2 - n);  // refraction: n'u' = n u - y c (n' - n)
    n = n2;
    if (i + 1 < kSeedDoubleGauss.size()) y += row[1] * nu / n;  // transfer
  }
  return -y / (nu / n);
}

TEST(Chromatic, SeedDoubleGaussAxialColourMatchesAnIndependentParaxialTrace) {
  const double expected = backFocalLength(656.2725) - backFocalLength(486.1327);
  const double axial = axialColorMm(test::libraryLens("dgauss-100mm"));
  std::printf("axial colour: library %.5f mm, independent %.5f mm\n", axial, expected);
  EXPECT_GT(expected, 0.05);  // undercorrected: red focuses behind blue
  EXPECT_NEAR(axial, expected, 0.01 * expected);
  // At the d line the independent trace gives the lecture's BFL (about 72.21 mm).
  EXPECT_NEAR(backFocalLength(587.5618), 72.21, 0.05);
}

TEST(Chromatic, LensWithoutAbbeNumbersHasNone) {
  LensPrescription rx = test::libraryLens("dgauss-100mm");
  EXPECT_TRUE(hasDispersion(rx));
  for (Surface& s : rx.surfaces) s.medium.vd = 0.0;
  EXPECT_FALSE(hasDispersion(rx));
  EXPECT_EQ(axialColorMm(rx), 0.0);
  const LensSystem lens(rx);
  const std::optional<LateralColor> lc = lateralColor(lens, 20.0);
  ASSERT_TRUE(lc);
  EXPECT_EQ(lc->um(), 0.0);
}

// Lateral colour is the F and C chief rays' heights on the film at the field
// whose d-line chief ray reaches the given height.
TEST(Chromatic, LateralColourIsTheChiefRaysSpreadAtThatField) {
  const LensSystem lens(test::libraryLens("dgauss-100mm"));
  const std::optional<LateralColor> lc = lateralColor(lens, 21.63);
  ASSERT_TRUE(lc);
  const double film = lens.paraxial().bfl;
  const FieldPoint field{lc->fieldAngleDeg, kInfinity};
  EXPECT_NEAR(std::abs(*chiefRayImageHeight(lens, field, film)), 21.63, 1e-6);
  const double f = std::abs(*chiefRayImageHeight(lens, field, film, kWavelengthFNm));
  const double c = std::abs(*chiefRayImageHeight(lens, field, film, kWavelengthCNm));
  EXPECT_NEAR(lc->um(), (f - c) * 1000.0, 1e-9);
  EXPECT_GT(std::abs(lc->um()), 0.5);  // a few micrometres for this design
  EXPECT_LT(std::abs(lc->um()), 50.0);
}

TEST(Chromatic, CurvesCrossZeroFocalShiftAtTheDLine) {
  const LensSystem lens(test::libraryLens("dgauss-100mm"));
  const ChromaticCurves c = chromaticCurves(lens, 21.63, 11);
  ASSERT_EQ(c.wavelengthNm.size(), 11u);
  ASSERT_EQ(c.imageHeightMm.size(), 11u);
  EXPECT_EQ(c.lateralColorUm.front(), 0.0);
  EXPECT_NEAR(c.lateralColorUm.back(), lateralColor(lens, 21.63)->um(), 1e-9);
  // The focal shift rises toward the red for an undercorrected lens and is
  // zero at the d line (between samples: interpolate).
  EXPECT_LT(c.focalShiftMm.front(), 0.0);
  EXPECT_GT(c.focalShiftMm.back(), 0.0);
  for (std::size_t i = 0; i + 1 < c.wavelengthNm.size(); ++i)
    if (c.wavelengthNm[i] <= kWavelengthDNm && c.wavelengthNm[i + 1] > kWavelengthDNm) {
      const double t = (kWavelengthDNm - c.wavelengthNm[i]) / (c.wavelengthNm[i + 1] - c.wavelengthNm[i]);
      EXPECT_NEAR(c.focalShiftMm[i] + t * (c.focalShiftMm[i + 1] - c.focalShiftMm[i]), 0.0, 0.002);
    }
}

}  // namespace
}  // namespace lensrt
