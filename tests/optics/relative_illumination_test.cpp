// Relative illumination against the closed forms of a stop behind a lens:
// the film sees the stop disc directly, so the projected solid angle is
// pi a^2 / (a^2 + d^2) on the axis and falls off as cos^4 off it.
#include "optics/relative_illumination.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

// A weak biconvex singlet with the stop 2 mm behind it, the stop being the
// last surface: rays from the film reach the stop before any glass.
LensSystem lensWithRearStop(double stopDiameter, double filmDistance) {
  LensPrescription rx;
  rx.name = "rear-stop";
  Surface front{100.0, 4.0, 30.0, {1.5, 60.0, "", std::nullopt}};
  Surface back{-100.0, 2.0, 30.0, {}};
  Surface stop{0.0, filmDistance, stopDiameter, {}};
  stop.isStop = true;
  rx.surfaces = {front, back, stop};
  return LensSystem(rx);
}

TEST(RelativeIllumination, OnAxisSolidAngleIsPiSinSquaredOfTheStopsHalfAngle) {
  const double a = 10.0, d = 100.0;
  const FilmIrradiance e = filmIrradiance(lensWithRearStop(2.0 * a, d), d, 0.0, 200);
  EXPECT_NEAR(e.projectedSolidAngle, kPi * a * a / (a * a + d * d), 0.005 * kPi * a * a / (a * a + d * d));
  EXPECT_NEAR(e.passingArea, kPi * a * a, 0.005 * kPi * a * a);
}

TEST(RelativeIllumination, SmallStopFollowsCosineFourth) {
  const double d = 100.0;
  const LensSystem lens = lensWithRearStop(2.0, d);
  const auto curve = relativeIlluminationCurve(lens, d, 30.0, 4, 48);
  ASSERT_EQ(curve.size(), 4u);
  EXPECT_DOUBLE_EQ(curve[0].relative, 1.0);
  for (const auto& p : curve) {
    const double cos2 = d * d / (d * d + p.filmRadiusMm * p.filmRadiusMm);
    EXPECT_NEAR(p.relative, cos2 * cos2, 2e-3) << "film radius " << p.filmRadiusMm;
    EXPECT_NEAR(p.areaRatio, 1.0, 1e-9) << "the stop alone limits the beam";
  }
  EXPECT_LT(curve.back().relative, 0.85);  // cos^4(16.7 deg) = 0.84: the falloff is measured
}

TEST(RelativeIllumination, DoubleGaussIsOneOnAxisAndFallsOffWithVignetting) {
  const LensSystem lens(loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-50mm.dat"));
  const double film = focusFilmDistance(lens, kInfinity);
  const auto curve = relativeIlluminationCurve(lens, film, 21.6, 4, 48);
  EXPECT_DOUBLE_EQ(curve.front().relative, 1.0);
  for (std::size_t i = 1; i < curve.size(); ++i) {
    EXPECT_LT(curve[i].relative, curve[i - 1].relative);
    // Wide open, the rim elements cut the oblique beams: below cos^4 alone.
    EXPECT_LT(curve[i].relative, curve[i].cos4);
    EXPECT_LT(curve[i].areaRatio, 1.0);
  }
  // Focused at infinity, the on-axis cone is the f-number's: pi / (4 N^2).
  const double n = lens.paraxial().fNumber;
  EXPECT_NEAR(filmIrradiance(lens, film, 0.0).projectedSolidAngle, kPi / (4.0 * n * n),
              0.03 * kPi / (4 * n * n));
}

}  // namespace
}  // namespace lensrt
