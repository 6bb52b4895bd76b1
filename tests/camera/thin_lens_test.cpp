// The thin lens against the seed's closed forms: conjugates, irradiance, depth of field.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "camera/pinhole_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/paraxial.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

using test::cameraRay;
using test::imageOf;
using test::pointAtZ;

ThinLensParams params(double f, double n, double focusM) {
  ThinLensParams p;
  p.focalLengthMm = f;
  p.fNumber = n;
  p.focusMetres = focusM;
  return p;
}

// Every ray from one film point meets the others at one point of the focus plane.
TEST(ThinLens, FocusPlanePointImagesToOneFilmPoint) {
  const ThinLensCamera cam(Transform(), test::testFilm(), params(50, 2, 3.0));
  SplitMix64 rng(7);
  for (const Vec2d raster : {Vec2d{320, 180}, Vec2d{50.5, 20.25}, Vec2d{600, 300}}) {
    const auto chief = cameraRay(cam, raster, {0.5, 0.5});
    ASSERT_TRUE(chief);
    const Vec3d target = pointAtZ(*chief, -3.0);
    for (int i = 0; i < 64; ++i) {
      const auto r = cameraRay(cam, raster, {rng.uniform(), rng.uniform()});
      ASSERT_TRUE(r);
      const Vec3d q = pointAtZ(*r, -3.0);
      // 1 um on the film is 1 um / m = 59 um at 3 m (m = v / s).
      const double magnification = cam.imageDistanceMm() / 3000.0;
      EXPECT_LT(length(q - target) * 1e3 * magnification, 1e-3) << "mm on the film";
    }
  }
}

// E / L = pi cos^4(theta) / (4 N^2) at infinity focus; normalized exposure
// divides by pi / (4 N^2), so the mean weight is cos^4(theta). At a finite
// focus the seed's E = L A cos^4 / Q^2 with Q the image distance.
TEST(ThinLens, WeightIntegratesToSeedIrradiance) {
  const FilmGeometry film = test::testFilm();
  for (const double n : {1.4, 2.8, 8.0})
    for (const double focusM : {kInfinity, 1.5}) {
      const double f = 35;
      const ThinLensCamera cam(Transform(), film, params(f, n, focusM));
      const double q = std::isinf(focusM) ? f : f * focusM * 1e3 / (focusM * 1e3 - f);
      for (const Vec2d raster : {Vec2d{320, 180}, Vec2d{480, 90}, Vec2d{0.5, 0.5}}) {
        SplitMix64 rng(11);
        double sum = 0;
        const int count = 4000;
        for (int i = 0; i < count; ++i) {
          CameraSample s;
          s.film = {float(raster.x), float(raster.y)};
          s.lens = {float(rng.uniform()), float(rng.uniform())};
          const auto r = cam.generateRay(s);
          ASSERT_TRUE(r);
          sum += r->weight;
        }
        const double x = (raster.x / film.width - 0.5) * film.sensorWidthMm;
        const double y = (0.5 - raster.y / film.height) * film.sensorHeightMm;
        const double theta = std::atan(std::hypot(x, y) / q);
        const double area = kPi * std::pow(f / (2 * n), 2);
        const double e = area * std::pow(std::cos(theta), 4) / (q * q);  // E / L
        EXPECT_NEAR(sum / count, e / (kPi / (4 * n * n)), 0.01 * e / (kPi / (4 * n * n)))
            << "f/" << n << " focus " << focusM << " m, theta " << theta * 180 / kPi << " deg";
        if (std::isinf(focusM)) {
          EXPECT_NEAR(e, kPi * std::pow(std::cos(theta), 4) / (4 * n * n), 1e-12);
        }
      }
    }
}

// Blur circle of an on-axis point at distance d: the cone from its image
// (v_d) through the aperture f/N, cut by the film at v: c = (f/N)|v_d - v|/v_d.
double measuredBlurMm(const ThinLensCamera& cam, double dM) {
  std::vector<Vec2d> pts;
  for (int k = 0; k < 32; ++k) {  // the aperture rim: the blur circle's edge
    // The concentric disk mapping sends the square's boundary to the rim.
    const double phi = 2 * kPi * k / 32, a = std::cos(phi), b = std::sin(phi);
    const double m = 0.5 * 0.999999 / std::max(std::abs(a), std::abs(b));
    const Vec2d lens{0.5 + m * a, 0.5 + m * b};
    const auto img = imageOf(cam, {0, 0, -dM}, lens, {320, 180});
    if (!img) return NAN;
    pts.push_back(*img);
  }
  return test::spread(pts) * 36.0 / 640.0;
}

TEST(ThinLens, BlurCircleAndDepthOfFieldMatchSeed) {
  const double f = 50, n = 4, s = 3000, c = 0.03;
  const ThinLensCamera cam(Transform(), test::testFilm(), params(f, n, s / 1000));
  const double v = f * s / (s - f);
  for (const double d : {1000.0, 2000.0, 6000.0, 20000.0}) {
    const double vd = f * d / (d - f);
    const double predicted = (f / n) * std::abs(vd - v) / vd;
    EXPECT_NEAR(measuredBlurMm(cam, d / 1000), predicted, 0.01 * predicted) << "d = " << d << " mm";
  }
  // Where the measured blur equals c, by bisection on the distance.
  const auto solve = [&](double lo, double hi) {
    const bool risingWithD = measuredBlurMm(cam, hi / 1000) > measuredBlurMm(cam, lo / 1000);
    for (int it = 0; it < 40; ++it) {
      const double mid = std::sqrt(lo * hi);
      ((measuredBlurMm(cam, mid / 1000) > c) == risingWithD ? hi : lo) = mid;
    }
    return std::sqrt(lo * hi);
  };
  const double dn = s * f * f / (f * f + n * c * (s - f));
  const double df = s * f * f / (f * f - n * c * (s - f));
  EXPECT_NEAR(solve(500, s), dn, 0.05 * dn);
  EXPECT_NEAR(solve(s, 1e6), df, 0.05 * df);
  const DepthOfField dof = depthOfField(f, n, c, s);
  EXPECT_NEAR(dof.nearLimit, dn, 1e-6 * dn);
  EXPECT_NEAR(dof.farLimit, df, 1e-6 * df);
}

// As the aperture closes, the thin lens becomes the pinhole whose field of
// view the lens has at that focus (image distance v).
TEST(ThinLens, BecomesThePinholeAsTheApertureCloses) {
  const FilmGeometry film = test::testFilm();
  const double f = 50, s = 2.0;
  const ThinLensCamera thin(Transform(), film, params(f, 1e5, s));
  const double v = f * s * 1e3 / (s * 1e3 - f);
  const PinholeCamera pin(Transform(), film, 2 * std::atan(film.sensorHeightMm / 2 / v));
  SplitMix64 rng(3);
  for (int i = 0; i < 200; ++i) {
    const Vec2d raster{rng.uniform() * 640, rng.uniform() * 360};
    const Vec2d lens{rng.uniform(), rng.uniform()};
    const auto a = cameraRay(thin, raster, lens), b = cameraRay(pin, raster, lens);
    ASSERT_TRUE(a && b);
    EXPECT_LT(length(Vec3d(a->direction) - Vec3d(b->direction)), 1e-5);
    EXPECT_LT(length(Vec3d(a->origin)), 1e-6);
  }
}

TEST(ThinLens, RejectsImpossibleFocus) {
  EXPECT_THROW(ThinLensCamera(Transform(), test::testFilm(), params(50, 2, 0.04)), std::invalid_argument);
  EXPECT_THROW(ThinLensCamera(Transform(), test::testFilm(), params(50, 0, 2)), std::invalid_argument);
}

}  // namespace
}  // namespace lensrt
