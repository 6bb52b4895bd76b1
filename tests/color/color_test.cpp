// The colour library against published values: the CIE tables, illuminant
// chromaticities, the IEC sRGB matrix, Lindbloom's Bradford matrix, and the
// RGB-to-spectrum table's round trip under D65.
#include <gtest/gtest.h>

#include <cmath>

#include "color/chromatic_adaptation.h"
#include "color/cie.h"
#include "color/color_space.h"
#include "color/illuminant.h"
#include "color/rgb_to_spectrum.h"

namespace lensrt {
namespace {

TEST(Cie, MatchingFunctionsAtKnownWavelengths) {
  EXPECT_NEAR(cieXyzMatching(555).y, 1.0, 1e-4);
  EXPECT_NEAR(cieXyzMatching(600).x, 1.0622, 1e-4);
  EXPECT_NEAR(cieXyzMatching(450).z, 1.7721, 1e-3);
  EXPECT_NEAR(cieXyzMatching(555.5).y, 0.5 * (cieXyzMatching(555).y + cieXyzMatching(556).y), 1e-12);
  EXPECT_EQ(cieXyzMatching(359).y, 0.0);
  EXPECT_EQ(cieXyzMatching(831).y, 0.0);
  double sum = 0;
  for (int nm = 360; nm <= 830; ++nm) sum += cieXyzMatching(nm).y;
  EXPECT_NEAR(sum, kCieYIntegral, 1e-4);
  // The equal-energy spectrum has Y = 1 and white chromaticity (1/3, 1/3).
  const Vec3d e = spectrumToXyz([](double) { return 1.0; });
  EXPECT_NEAR(e.y, 1.0, 1e-6);
  EXPECT_NEAR(chromaticity(e).x, 1.0 / 3, 1e-4);
  EXPECT_NEAR(chromaticity(e).y, 1.0 / 3, 1e-4);
}

TEST(Illuminant, ChromaticitiesMatchTheCie) {
  const Vec2d d65xy = chromaticity(spectrumToXyz([](double nm) { return d65(nm); }));
  EXPECT_NEAR(d65xy.x, 0.3127, 1e-4);
  EXPECT_NEAR(d65xy.y, 0.3290, 1e-4);
  EXPECT_EQ(d65(560), 100.0);
  // The daylight formula at 6504 K is D65 (CIE 15: x_D = 0.31271).
  const Vec2d day = chromaticity(whiteXyz(6504));
  EXPECT_NEAR(day.x, 0.3127, 2e-4);
  EXPECT_NEAR(day.y, 0.3291, 2e-4);
  EXPECT_NEAR(daylightSpectrum(6504, 560), 100.0, 1e-9);
  // D50 (5003 K): (0.3457, 0.3585).
  const Vec2d d50 = chromaticity(whiteXyz(5003));
  EXPECT_NEAR(d50.x, 0.3457, 2e-4);
  EXPECT_NEAR(d50.y, 0.3585, 2e-4);
  // Illuminant A is a black body at 2856 K: (0.44757, 0.40745).
  const Vec2d a = chromaticity(whiteXyz(2856));
  EXPECT_NEAR(a.x, 0.44757, 1e-3);
  EXPECT_NEAR(a.y, 0.40745, 1e-3);
  // Wien: a black body peaks at 2.898e6 nm K / T.
  EXPECT_NEAR(blackbodySpectrum(5000, 2.8977721e6 / 5000), 1.0, 1e-12);
  EXPECT_LT(blackbodySpectrum(5000, 2.8977721e6 / 5000 + 5), 1.0);
  EXPECT_THROW(daylightSpectrum(3000, 500), std::invalid_argument);
}

TEST(ColorSpace, SrgbMatrixIsIec61966) {
  const ColorSpace& s = colorSpace(ColorSpaceId::Srgb);
  const double iec[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(s.rgbToXyz(i, j), iec[i][j], 1e-4) << i << "," << j;
  for (const ColorSpaceId id :
       {ColorSpaceId::Srgb, ColorSpaceId::Rec2020, ColorSpaceId::AcesCg, ColorSpaceId::Xyz}) {
    const ColorSpace& c = colorSpace(id);
    const Mat3d identity = c.xyzToRgb * c.rgbToXyz;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(identity(i, j), i == j ? 1.0 : 0.0, 1e-12);
    // RGB (1, 1, 1) is the white, Y = 1.
    const Vec3d w = c.rgbToXyz * Vec3d{1, 1, 1};
    EXPECT_NEAR(w.y, 1.0, 1e-12);
    EXPECT_NEAR(chromaticity(w).x, c.white.x, 1e-12);
    EXPECT_EQ(parseColorSpace(c.name), id);
  }
  // Rec. 2020's published matrix row for Y: 0.2627, 0.6780, 0.0593.
  const ColorSpace& r = colorSpace(ColorSpaceId::Rec2020);
  EXPECT_NEAR(r.rgbToXyz(1, 0), 0.2627, 1e-4);
  EXPECT_NEAR(r.rgbToXyz(1, 1), 0.6780, 1e-4);
  EXPECT_NEAR(r.rgbToXyz(1, 2), 0.0593, 1e-4);
  EXPECT_FALSE(parseColorSpace("adobergb"));
}

TEST(ChromaticAdaptation, BradfordD65ToD50IsLindbloomsMatrix) {
  const Vec3d d65{0.95047, 1.0, 1.08883}, d50{0.96422, 1.0, 0.82521};
  const Mat3d m = bradfordAdaptation(d65, d50);
  const double lindbloom[3][3] = {{1.0478112, 0.0228866, -0.0501270},
                                  {0.0295424, 0.9904844, -0.0170491},
                                  {-0.0092345, 0.0150436, 0.7521316}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(m(i, j), lindbloom[i][j], 1e-6) << i << "," << j;
  const Vec3d w = m * d65;
  EXPECT_NEAR(w.x, d50.x, 1e-12);
  EXPECT_NEAR(w.z, d50.z, 1e-12);
}

// The colour of table(rgb) under D65, integrated at 1 nm, back in sRGB.
Vec3d roundTrip(const Vec3f& rgb) {
  const SigmoidPolynomial s = RgbToSpectrumTable::srgb()(rgb);
  const Vec3d white = spectrumToXyz([](double nm) { return d65(nm); });
  const Vec3d xyz = spectrumToXyz([&](double nm) { return s(float(nm)) * d65(nm); }) / white.y;
  return colorSpace(ColorSpaceId::Srgb).xyzToRgb * xyz;
}

TEST(RgbToSpectrum, ReflectancesRoundTripUnderD65) {
  double worst = 0;
  for (int r = 0; r <= 8; ++r)
    for (int g = 0; g <= 8; ++g)
      for (int b = 0; b <= 8; ++b) {
        const Vec3f rgb{r / 8.0f, g / 8.0f, b / 8.0f};
        const Vec3d back = roundTrip(rgb);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(back[c] - rgb[c]));
      }
  // The fit is within about 3e-4 on the gamut's edges and far closer inside
  // (the tabulated D65's white is 1e-4 off sRGB's nominal one).
  EXPECT_LT(worst, 1e-3);
  // Greys are flat, and the spectra are reflectances.
  for (const float v : {0.0f, 0.18f, 0.5f, 1.0f}) {
    const SigmoidPolynomial s = RgbToSpectrumTable::srgb()({v, v, v});
    EXPECT_NEAR(s(400), v, 1e-6);
    EXPECT_NEAR(s(700), v, 1e-6);
  }
  for (const Vec3f rgb : {Vec3f{1, 0, 0}, Vec3f{0, 1, 0}, Vec3f{0, 0, 1}, Vec3f{0.9f, 0.8f, 0.1f}}) {
    const SigmoidPolynomial s = RgbToSpectrumTable::srgb()(rgb);
    EXPECT_LE(s.maxValue(), 1.0f);
    for (float nm = 360; nm <= 830; nm += 10) EXPECT_GE(s(nm), 0.0f);
  }
  // Red reflects long wavelengths, blue short ones.
  EXPECT_GT(RgbToSpectrumTable::srgb()({1, 0, 0})(650), 0.9f);
  EXPECT_LT(RgbToSpectrumTable::srgb()({1, 0, 0})(450), 0.05f);
  EXPECT_GT(RgbToSpectrumTable::srgb()({0, 0, 1})(450), 0.9f);
}

}  // namespace
}  // namespace lensrt
