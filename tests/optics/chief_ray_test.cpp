// The chief-ray projection (optics/chief_ray.h) against what defines it: the
// ray from the point through the stop's centre, found here by the distortion
// code's independent scan and bisection (chiefRayImageHeight), by the spot
// of a nearly closed stop (its centroid tends to the chief ray) and by
// tracing the rays it returns.
#include "optics/chief_ray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/constants.h"
#include "core/warnings.h"
#include "optics/distortion.h"
#include "optics/focus.h"
#include "optics/spot_diagram.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

constexpr double kDeg = kPi / 180.0;

struct Case {
  std::string lens;
  double maxFieldDeg;  // within the 36 x 24 mm frame's half diagonal
  double filmScale;    // of the frame's corner: the fisheye's image circle is 28 mm across
};

const Case kCases[] = {{"dgauss-50mm", 23.0, 1.0},
                       {"wide-22mm", 44.0, 1.0},
                       {"fisheye-10mm", 64.0, 0.6},
                       {"telephoto-250mm", 4.9, 1.0},
                       {"canon-rf50-51mm", 22.0, 1.0}};

// The independent reference: the meridional pass band scanned, the chief ray
// bisected on its stop height (optics/distortion.cpp).
TEST(ChiefRays, ImageHeightsMatchTheDistortionCodesScanAtInfinityAndNear) {
  for (const Case& c : kCases) {
    const LensSystem lens(test::libraryLens(c.lens));
    for (const double focusMm : {kInfinity, 2000.0}) {
      const double filmZ = lens.rearZ() + focusFilmDistance(lens, focusMm);
      const ChiefRays rays(lens, filmZ);
      for (const double fraction : {0.02, 0.3, 0.7, 1.0}) {
        const double angle = fraction * c.maxFieldDeg;
        const std::optional<double> expected =
            chiefRayImageHeight(lens, {angle, focusMm}, filmZ - lens.rearZ());
        ASSERT_TRUE(expected) << c.lens << " " << angle;
        // The same field as FieldPoint has it: the object toward +x.
        const ChiefRayImage got =
            std::isinf(focusMm) ? rays.ofDirection({-std::sin(angle * kDeg), 0.0, std::cos(angle * kDeg)})
                                : rays.ofPoint({focusMm * std::tan(angle * kDeg), 0.0,
                                                lens.paraxial().entrancePupilZ - focusMm});
        ASSERT_EQ(got.status, ChiefRayStatus::Passes) << c.lens << " " << angle;
        // The scan bisects to ~1e-9 of its band: agreement to 1e-6 mm (0.03 px of 30 um).
        EXPECT_NEAR(got.film.x, *expected, 1e-6) << c.lens << " field " << angle << " focus " << focusMm;
        EXPECT_NEAR(got.film.y, 0.0, 1e-12);
      }
    }
  }
}

TEST(ChiefRays, FilmPointRaysCrossTheStopCentreAndProjectBack) {
  for (const Case& c : kCases) {
    const LensSystem lens(test::libraryLens(c.lens));
    const double filmZ = lens.rearZ() + focusFilmDistance(lens, 3000.0);
    const ChiefRays rays(lens, filmZ);
    const int stopHit = lens.surfaceCount() - 1 - lens.paraxial().stopIndex;
    for (const Vec2d corner : {Vec2d{0.0, 0.0}, Vec2d{3.0, -1.0}, Vec2d{-10.0, 7.0}, Vec2d{17.5, 11.5}}) {
      const Vec2d film = corner * c.filmScale;
      const ChiefRayToScene out = rays.ofFilmPoint(film);
      ASSERT_EQ(out.status, ChiefRayStatus::Passes) << c.lens << " " << film.x << "," << film.y;
      // Traced again from the film along the same line: through the stop's centre.
      std::vector<Vec3d> path;
      const Vec3d origin{film.x, film.y, filmZ};
      const std::optional<LensRay> rear =
          lens.traceFromScene({out.ray.origin + out.ray.direction * 5.0, -out.ray.direction});
      ASSERT_TRUE(rear);
      const double t = (filmZ - rear->origin.z) / rear->direction.z;
      EXPECT_NEAR(rear->origin.x + rear->direction.x * t, film.x, 1e-9) << c.lens;
      EXPECT_NEAR(rear->origin.y + rear->direction.y * t, film.y, 1e-9) << c.lens;
      ASSERT_TRUE(lens.traceFromFilm({origin, rear->origin - origin}, kWavelengthDNm, &path));
      EXPECT_NEAR(path[std::size_t(stopHit)].x, 0.0, 1e-9) << c.lens;
      EXPECT_NEAR(path[std::size_t(stopHit)].y, 0.0, 1e-9) << c.lens;
      // Any point along the ray, and its direction from infinity, project back to the film point.
      for (const double along : {100.0, 2500.0}) {
        const ChiefRayImage p = rays.ofPoint(out.ray.origin + out.ray.direction * along);
        ASSERT_EQ(p.status, ChiefRayStatus::Passes);
        EXPECT_NEAR(p.film.x, film.x, 1e-8) << c.lens << " along " << along;
        EXPECT_NEAR(p.film.y, film.y, 1e-8) << c.lens << " along " << along;
      }
      const ChiefRayImage inf = rays.ofDirection(-out.ray.direction);
      EXPECT_NEAR(inf.film.x, film.x, 1e-8) << c.lens;
      EXPECT_NEAR(inf.film.y, film.y, 1e-8) << c.lens;
    }
  }
}

// Stopped down to f/90 the spot of a point shrinks about its chief ray:
// the centroid of uniformly spread rays tends to it (coma shifts it by the
// square of the stop's radius). The spot code knows nothing of chief rays.
TEST(ChiefRays, ASpotThroughANearlyClosedStopCentresOnTheChiefRay) {
  for (const Case& c : kCases) {
    Warnings quiet;
    const LensSystem lens(stopDown(test::libraryLens(c.lens), 90.0, quiet));
    const double filmDistance = focusFilmDistance(lens, 1500.0);
    const ChiefRays rays(lens, lens.rearZ() + filmDistance);
    for (const double fraction : {0.5, 0.95}) {
      const double angle = fraction * c.maxFieldDeg;
      const SpotDiagram spot = spotDiagram(lens, {angle, 1500.0}, filmDistance, 41);
      ASSERT_GT(spot.points.size(), 100u) << c.lens;
      const ChiefRayImage chief =
          rays.ofPoint({1500.0 * std::tan(angle * kDeg), 0.0, lens.paraxial().entrancePupilZ - 1500.0});
      // Measured within 0.1 um (telephoto-250mm at the corner: 0.091 um);
      // 0.2 um is a 150th of a 30 um pixel.
      EXPECT_NEAR(chief.film.x, spot.centroid.x, 2e-4) << c.lens << " field " << angle;
    }
  }
}

TEST(ChiefRays, RotationalSymmetryAndWavelength) {
  const LensSystem lens(test::libraryLens("dgauss-100mm"));
  const ChiefRays rays(lens, lens.rearZ() + focusFilmDistance(lens, kInfinity));
  const ChiefRayImage x = rays.ofPoint({300.0, 0.0, -2000.0});
  for (const double phi : {0.7, 2.0, -2.5}) {
    const ChiefRayImage r = rays.ofPoint({300.0 * std::cos(phi), 300.0 * std::sin(phi), -2000.0});
    EXPECT_NEAR(r.film.x, x.film.x * std::cos(phi), 1e-10);
    EXPECT_NEAR(r.film.y, x.film.x * std::sin(phi), 1e-10);
  }
  // dgauss-100mm has dispersion: lateral colour moves the chief ray's image
  // by micrometres between F and C (lens info: 3.11 um at the 36 x 24 mm
  // frame's corner, on the film at the paraxial focus).
  const double film = lens.paraxial().bfl;
  const ChiefRays atFocus(lens, lens.rearZ() + film);
  const double angle = *fieldAngleForImageHeight(lens, kInfinity, film, std::hypot(18.0, 12.0));
  const Vec3d corner{-std::sin(angle * kDeg), 0.0, std::cos(angle * kDeg)};
  const double f = atFocus.ofDirection(corner, kWavelengthFNm).film.x;
  const double c = atFocus.ofDirection(corner, kWavelengthCNm).film.x;
  EXPECT_NEAR(f, *chiefRayImageHeight(lens, {angle, kInfinity}, film, kWavelengthFNm), 1e-6);
  EXPECT_NEAR(c, *chiefRayImageHeight(lens, {angle, kInfinity}, film, kWavelengthCNm), 1e-6);
  EXPECT_NEAR((std::abs(f) - std::abs(c)) * 1000.0, 3.11, 0.01);
}

TEST(ChiefRays, BehindAndOutsideTheFieldAreFlagged) {
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  const ChiefRays rays(lens, lens.rearZ() + focusFilmDistance(lens, kInfinity));
  EXPECT_EQ(rays.ofPoint({0.0, 0.0, 5.0}).status, ChiefRayStatus::Behind);
  EXPECT_EQ(rays.ofDirection({0.0, 0.0, -1.0}).status, ChiefRayStatus::Behind);
  // 80 degrees off axis: no ray of a double Gauss gets through.
  const ChiefRayImage wide = rays.ofDirection({-std::sin(80 * kDeg), 0.0, std::cos(80 * kDeg)});
  EXPECT_EQ(wide.status, ChiefRayStatus::Blocked);
  // The axis images at the centre.
  const ChiefRayImage axis = rays.ofPoint({0.0, 0.0, -1000.0});
  EXPECT_EQ(axis.status, ChiefRayStatus::Passes);
  EXPECT_EQ(axis.film.x, 0.0);
}

}  // namespace
}  // namespace lensrt

namespace lensrt {
namespace {

// A solve started from a nearby point's (ChiefRayHint, as flow passes a
// pixel's solves on) converges to the table-started solve's image: the
// start moves only the last bits. A wrong hint costs traces, not accuracy.
TEST(ChiefRays, AHintedSolveLandsWhereATableStartedOneDoes) {
  for (const char* name : {"dgauss-50mm", "wide-22mm", "canon-rf50-51mm"}) {
    const LensSystem lens(test::libraryLens(name));
    const ChiefRays rays(lens, lens.rearZ() + focusFilmDistance(lens, 2000.0));
    double worst = 0.0;
    int hinted = 0;
    for (int i = 0; i < 300; ++i) {
      // A pixel's samples: points a fraction of a millimetre apart, 1.5 to 3 m away.
      const Vec3d centre{(i % 20 - 9.5) * 40.0, (i / 20 - 7.0) * 40.0, -1500.0 - 5.0 * i};
      ChiefRayHint hint;
      for (int k = 0; k < 8; ++k) {
        const Vec3d p = centre + Vec3d{0.1 * (k % 3), -0.07 * k, 0.2 * (k % 2)};
        const bool had = hint.valid();
        const ChiefRayImage plain = rays.ofPoint(p);
        const ChiefRayImage started = rays.ofPoint(p, kWavelengthDNm, &hint);
        ASSERT_EQ(started.status, plain.status) << name << " " << i << " " << k;
        if (plain.status != ChiefRayStatus::Passes) continue;
        hinted += had;
        EXPECT_TRUE(hint.valid()) << name << " " << i << " " << k;
        worst = std::max(worst, std::hypot(started.film.x - plain.film.x, started.film.y - plain.film.y));
      }
    }
    EXPECT_GT(hinted, 1000) << name;
    EXPECT_LT(worst, 1e-8) << name << ": mm on the film";  // 1e-8 mm: 2e-6 of a 5 um pixel
    // Wrong starts: a crossing far off, a rate of the wrong sign or size.
    const Vec3d p{310.0, -190.0, -2100.0};
    const ChiefRayImage plain = rays.ofPoint(p);
    for (const ChiefRayHint bad : {ChiefRayHint{-400.0f, 30.0f, 1.0f}, ChiefRayHint{-2090.0f, 0.0f, -3.0f},
                                   ChiefRayHint{20.0f, 0.0f, 1e-6f}, ChiefRayHint{-30.0f, -5.0f, 1e6f}}) {
      ChiefRayHint hint = bad;
      const ChiefRayImage started = rays.ofPoint(p, kWavelengthDNm, &hint);
      ASSERT_EQ(started.status, plain.status) << name;
      EXPECT_NEAR(started.film.x, plain.film.x, 1e-8) << name << " " << bad.axisZ;
      EXPECT_NEAR(started.film.y, plain.film.y, 1e-8) << name << " " << bad.axisZ;
    }
  }
}

}  // namespace
}  // namespace lensrt
