// Distortion from the real chief ray against closed-form expectations.
#include "optics/distortion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/focus.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

// Two identical meniscus-biconvex singlets mirrored about a central stop.
LensSystem symmetricLens() {
  LensPrescription rx;
  rx.name = "symmetric";
  Surface s1{40.0, 6.0, 30.0, {1.6, 50.0, "", std::nullopt}};
  Surface s2{200.0, 6.0, 30.0, {}};
  Surface stop{0.0, 6.0, 12.0, {}};
  stop.isStop = true;
  Surface s3{-200.0, 6.0, 30.0, {1.6, 50.0, "", std::nullopt}};
  Surface s4{-40.0, 0.0, 30.0, {}};
  rx.surfaces = {s1, s2, stop, s3, s4};
  return LensSystem(rx);
}

TEST(Distortion, SymmetricLensAtUnitMagnificationHasNone) {
  const LensSystem lens = symmetricLens();
  const ParaxialData& p = lens.paraxial();
  // Object 2f in front of H images at 2f behind H' with m = -1.
  const double objectFromPupil = p.entrancePupilZ - (p.frontPrincipalZ - 2.0 * p.efl);
  ASSERT_NEAR(paraxialConjugate(p, objectFromPupil).magnification, -1.0, 1e-9);
  const double film = focusFilmDistance(lens, objectFromPupil);
  const auto curve = distortionCurve(lens, objectFromPupil, film, 10.0, 6);
  ASSERT_EQ(curve.size(), 6u);
  EXPECT_NEAR(curve.back().realHeightMm, 10.0, 1e-3);
  for (const auto& d : curve) EXPECT_NEAR(d.percent, 0.0, 1e-3) << "angle " << d.fieldAngleDeg;
  // The same lens at infinity is not symmetric in use: distortion appears.
  const double filmInf = focusFilmDistance(lens, kInfinity);
  EXPECT_GT(std::abs(distortionCurve(lens, kInfinity, filmInf, 10.0, 3).back().percent), 0.05);
}

TEST(Distortion, ChiefRayCrossesTheStopCentreAndImageIsInverted) {
  const LensSystem lens = symmetricLens();
  const FieldPoint field{10.0, kInfinity};
  const auto aim = chiefRayAim(lens, field);
  ASSERT_TRUE(aim);
  std::vector<Vec3d> path;
  ASSERT_TRUE(lens.traceFromScene(fieldRay(lens, field, {*aim, 0.0}), kWavelengthDNm, &path));
  EXPECT_NEAR(path[2].x, 0.0, 1e-9);
  const double film = focusFilmDistance(lens, kInfinity);
  const auto y = chiefRayImageHeight(lens, field, film);
  ASSERT_TRUE(y);
  EXPECT_LT(*y, 0.0);
  // Paraxial limit: a small field images at f tan(theta).
  const auto y1 = chiefRayImageHeight(lens, {0.1, kInfinity}, film);
  EXPECT_NEAR(-*y1, lens.paraxial().efl * std::tan(0.1 * kPi / 180.0), 1e-4);
}

TEST(Distortion, FisheyeHasStrongBarrelDistortion) {
  const LensSystem lens(loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/fisheye-10mm.dat"));
  const double film = focusFilmDistance(lens, kInfinity);
  const FieldLimit limit = fieldForImageHeight(lens, kInfinity, film, 21.6);
  EXPECT_FALSE(limit.reachedTarget) << "a circular fisheye: its image circle is smaller than 36x24";
  EXPECT_GT(limit.angleDeg, 60.0);
  const auto curve = distortionCurve(lens, kInfinity, film, 21.6, 5);
  EXPECT_LT(curve.back().percent, -30.0);
  for (std::size_t i = 2; i < curve.size(); ++i) EXPECT_LT(curve[i].percent, curve[i - 1].percent);
}

}  // namespace
}  // namespace lensrt
