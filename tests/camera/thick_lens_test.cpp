// The thick lens: the seed's projection, and agreement with the full lens
// it is derived from near the axis.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "camera/lens_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/paraxial.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

using test::cameraRay;
using test::imageOf;
using test::pointAtZ;

ThickLensParams lectureThick(double fNumber, double focusM) {
  return thickLensFromParaxial(computeParaxial(test::lectureDoubleGauss(0.5)), fNumber, focusM);
}

TEST(ThickLens, FocusPlanePointImagesToOneFilmPoint) {
  const ThickLensCamera cam(Transform(), test::testFilm(), lectureThick(2, 1.2));
  SplitMix64 rng(2);
  for (const Vec2d raster : {Vec2d{320, 180}, Vec2d{10, 350}, Vec2d{500, 40}}) {
    const auto chief = cameraRay(cam, raster, {0.5, 0.5});
    ASSERT_TRUE(chief);
    const Vec3d target = pointAtZ(*chief, -1.2);
    for (int i = 0; i < 64; ++i) {
      const auto r = cameraRay(cam, raster, {rng.uniform(), rng.uniform()});
      ASSERT_TRUE(r);
      // Object-space error times the magnification: microns on the film.
      const double m = cam.imageDistance() / cam.objectDistanceFromH();
      EXPECT_LT(length(pointAtZ(*r, -1.2) - target) * 1e3 * m, 1e-3);
    }
  }
}

// The seed's projection: z' = f z/(z+f) + t, x' = (z'-t) x/z, with z and x
// measured from the front principal point (z < 0 in front), z' from H.
TEST(ThickLens, ImagesWhereTheSeedProjectionSays) {
  const ThickLensParams P = lectureThick(4, 0.8);
  const ThickLensCamera cam(Transform(), test::testFilm(), P);
  const double f = P.focalLengthMm, t = P.rearPrincipalZ - P.frontPrincipalZ;
  const double zFocus = -(800.0 + (P.frontPrincipalZ - P.entrancePupilZ));  // from H, negative
  const double zpFocus = f * zFocus / (zFocus + f) + t;
  EXPECT_NEAR(cam.filmZ() - P.frontPrincipalZ, zpFocus, 1e-9);
  for (const Vec2d obj : {Vec2d{30, 0}, Vec2d{-50, 80}, Vec2d{100, 60}}) {  // mm, in the focus plane
    const double xp = (zpFocus - t) * obj.x / zFocus, yp = (zpFocus - t) * obj.y / zFocus;
    // Object point in camera space: the camera origin is the entrance pupil.
    const Vec3d p{obj.x * 1e-3, obj.y * 1e-3, (zFocus + P.frontPrincipalZ - P.entrancePupilZ) * 1e-3};
    const auto img = imageOf(cam, p, {0.3, 0.7}, {320, 180});
    ASSERT_TRUE(img);
    // Upright raster: the physical image (xp, yp) is inverted, so upright = -xp.
    const double ux = (img->x / 640.0 - 0.5) * 36.0, uy = (0.5 - img->y / 360.0) * 20.25;
    EXPECT_NEAR(ux, -xp, 1e-4);
    EXPECT_NEAR(uy, -yp, 1e-4);
  }
}

// Near the axis the full lens is its paraxial (thick) model: image heights of
// points in the focus plane agree within 0.5%, and both equal the paraxial
// magnification times the object height.
TEST(ThickLens, AgreesWithTheFullLensNearTheAxis) {
  Warnings warnings;
  const double focusM = 2.0, n = 8;
  LensCameraParams lp;
  lp.fNumber = n;
  lp.focusMetres = focusM;
  const LensCamera full(Transform(), test::testFilm(), test::lectureDoubleGauss(0.5), lp, Exposure{},
                        warnings);
  const ThickLensCamera thick(Transform(), test::testFilm(), lectureThick(n, focusM));
  const double m = paraxialConjugate(full.lens().paraxial(), focusM * 1e3).magnification;
  for (const double h : {0.02, 0.05, 0.1}) {  // metres off axis; up to ~2.5 mm on the film
    const Vec3d p{h, 0.0, -focusM};
    const auto meanImage = [&](const Camera& cam) {
      SplitMix64 rng(5);
      double sx = 0;
      int count = 0;
      for (int i = 0; i < 40; ++i)
        if (const auto img = imageOf(cam, p, {rng.uniform(), rng.uniform()}, {330, 180})) {
          sx += (img->x / 640.0 - 0.5) * 36.0;
          ++count;
        }
      return count ? sx / count : NAN;
    };
    const double xFull = meanImage(full), xThick = meanImage(thick);
    const double expected = -m * h * 1e3;  // upright image height (m < 0: inverted)
    EXPECT_NEAR(xThick, xFull, 0.005 * std::abs(xFull)) << "h = " << h;
    EXPECT_NEAR(xThick, expected, 0.001 * std::abs(expected));
    EXPECT_NEAR(xFull, expected, 0.005 * std::abs(expected));
  }
}

}  // namespace
}  // namespace lensrt
