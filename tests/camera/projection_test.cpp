// The cameras' projections (camera/projection.h) against closed forms, the
// cameras' own rendering rays and each other.
#include "camera/projection.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "camera/film_mapping.h"
#include "camera/lens_camera.h"
#include "camera/orthographic_camera.h"
#include "camera/pinhole_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/focus.h"
#include "optics/glass.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

constexpr double kD = kWavelengthDNm;

ThinLensParams thin(double focusM) {
  ThinLensParams p;
  p.focalLengthMm = 50.0;
  p.fNumber = 2.0;
  p.focusMetres = focusM;
  return p;
}

std::unique_ptr<LensCamera> fullLens(const LensPrescription& rx, double focusM, bool dispersion = false,
                                     const Transform& pose = Transform(),
                                     FilmGeometry film = test::testFilm()) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = 4.0;
  p.focusMetres = focusM;
  p.dispersion = dispersion;
  return std::make_unique<LensCamera>(pose, film, rx, p, Exposure{}, warnings);
}

LensPrescription library(const char* name) {
  return loadLens(findLens(name, std::filesystem::path(LENSRT_SOURCE_DIR) / "lenses"));
}

// Pixel (0, 0)'s corner is the raster origin, y down; camera space looks
// down -Z with +Y up: a point up and to the left images up and to the left.
TEST(Projection, PinholeClosedFormAndConventions) {
  const FilmGeometry film = test::testFilm();  // 640 x 360, 56.25 um pixels
  const double yfov = 40.0 * kPi / 180.0;
  const PinholeCamera cam(Transform(), film, yfov);
  // The focal length in pixels: half the height over tan(yfov / 2).
  const double fpx = 0.5 * film.height / std::tan(0.5 * yfov);
  const Vec3d p{-0.3, 0.2, -2.0};
  const ProjectedPoint q = cam.projectCameraPoint(p, kD);
  EXPECT_EQ(q.visibility, Visibility::Visible);
  EXPECT_NEAR(q.raster.x, 320.0 + fpx * -0.3 / 2.0, 1e-9);
  EXPECT_NEAR(q.raster.y, 180.0 - fpx * 0.2 / 2.0, 1e-9);
  EXPECT_LT(q.raster.x, 320.0);
  EXPECT_LT(q.raster.y, 180.0);
  const ProjectedPoint centre = cam.projectCameraPoint({0.0, 0.0, -5.0}, kD);
  EXPECT_EQ(centre.raster.x, 320.0);
  EXPECT_EQ(centre.raster.y, 180.0);
  EXPECT_EQ(cam.projectCameraPoint({0.0, 0.0, 1.0}, kD).visibility, Visibility::Behind);
  EXPECT_EQ(cam.projectCameraPoint({5.0, 0.0, -1.0}, kD).visibility, Visibility::OutsideFrame);
  // The rendering's ray through pixel (10, 20)'s centre sees what projects there.
  const auto r = test::cameraRay(cam, {10.5, 20.5}, {0.5, 0.5});
  ASSERT_TRUE(r);
  const ProjectedPoint back = cam.projectCameraPoint(test::pointAtZ(*r, -3.0), kD);
  EXPECT_NEAR(back.raster.x, 10.5, 1e-4);
  EXPECT_NEAR(back.raster.y, 20.5, 1e-4);
}

TEST(Projection, OrthographicClosedForm) {
  const OrthographicCamera cam(Transform(), test::testFilm(), 2.0);  // 2 m up from the centre
  const ProjectedPoint q = cam.projectCameraPoint({1.0, 1.0, -7.0}, kD);
  EXPECT_NEAR(q.raster.x, 320.0 + 1.0 / (2.0 * 640.0 / 360.0) * 320.0, 1e-9);
  EXPECT_NEAR(q.raster.y, 90.0, 1e-9);
  const ProjectedRay ray = cam.unprojectRaster(q.raster, kD);
  EXPECT_NEAR(ray.origin.x, 1.0, 1e-12);
  EXPECT_NEAR(ray.origin.y, 1.0, 1e-12);
}

// The thin lens's chief ray passes its centre undeviated: the image of a
// point at depth Z is the pinhole's scaled to the film at v, in focus or
// not; the rendering's ray through the aperture's centre (lens sample
// (0.5, 0.5)) lands there too.
TEST(Projection, ThinLensClosedFormInAndOutOfFocus) {
  const ThinLensCamera cam(Transform(), test::testFilm(), thin(2.0));
  const double v = 50.0 * 2000.0 / (2000.0 - 50.0), pitch = 36.0 / 640.0;
  for (const Vec3d p : {Vec3d{0.1, -0.05, -2.0}, Vec3d{-0.2, 0.1, -0.7}, Vec3d{0.4, 0.3, -9.0}}) {
    const ProjectedPoint q = cam.projectCameraPoint(p, kD);
    EXPECT_NEAR(q.raster.x, 320.0 + v * (p.x / -p.z) / pitch, 1e-9);
    EXPECT_NEAR(q.raster.y, 180.0 - v * (p.y / -p.z) / pitch, 1e-9);
    const std::optional<Vec2d> rendered = test::imageOf(cam, p, {0.5, 0.5}, q.raster);
    ASSERT_TRUE(rendered);
    EXPECT_NEAR(rendered->x, q.raster.x, 2e-3);
    EXPECT_NEAR(rendered->y, q.raster.y, 2e-3);
  }
}

// The thick lens: the rendering's ray through the exit pupil's centre is
// the chief ray; a point in focus images there from every aperture sample.
TEST(Projection, ThickLensMatchesItsRaysThroughThePupilCentre) {
  const ParaxialData paraxial = computeParaxial(test::lectureDoubleGauss(0.5));
  const ThickLensCamera cam(Transform(), test::testFilm(), thickLensFromParaxial(paraxial, 2.0, 1.5));
  for (const Vec3d p : {Vec3d{0.1, -0.05, -1.5}, Vec3d{-0.2, 0.1, -0.6}, Vec3d{0.9, 0.4, -8.0}}) {
    const ProjectedPoint q = cam.projectCameraPoint(p, kD);
    ASSERT_EQ(q.visibility, Visibility::Visible);
    const std::optional<Vec2d> rendered = test::imageOf(cam, p, {0.5, 0.5}, q.raster);
    ASSERT_TRUE(rendered);
    EXPECT_NEAR(rendered->x, q.raster.x, 2e-3) << p.z;
    EXPECT_NEAR(rendered->y, q.raster.y, 2e-3) << p.z;
  }
  // In focus (1.5 m from the entrance pupil): another aperture sample agrees.
  const Vec3d inFocus{0.12, 0.07, -1.5};
  const ProjectedPoint q = cam.projectCameraPoint(inFocus, kD);
  const std::optional<Vec2d> edge = test::imageOf(cam, inFocus, {0.9, 0.2}, q.raster);
  ASSERT_TRUE(edge);
  EXPECT_NEAR(edge->x, q.raster.x, 2e-3);
  EXPECT_NEAR(edge->y, q.raster.y, 2e-3);
}

// Near the axis the real lens is its paraxial model: the full lens and the
// thick lens made from its paraxial data project a small field alike (the
// same conventions: inversion, entrance pupil origin, raster).
TEST(Projection, FullLensMatchesItsThickModelNearTheAxis) {
  const LensPrescription rx = test::lectureDoubleGauss(0.5);
  const auto lens = fullLens(rx, 1.5);
  const ThickLensCamera thick(Transform(), test::testFilm(),
                              thickLensFromParaxial(computeParaxial(rx), 4.0, 1.5));
  for (const Vec3d p : {Vec3d{0.004, -0.003, -1.5}, Vec3d{-0.002, 0.002, -0.8}, Vec3d{0.01, 0.005, -6.0}}) {
    const ProjectedPoint a = lens->projectCameraPoint(p, kD);
    const ProjectedPoint b = thick.projectCameraPoint(p, kD);
    ASSERT_EQ(a.visibility, Visibility::Visible);
    // Within 0.2% of the offset from the centre (third-order terms, and the
    // film the exact focus puts a few um from the paraxial one).
    EXPECT_NEAR(a.raster.x - 320.0, b.raster.x - 320.0, 2e-3 * std::abs(b.raster.x - 320.0)) << p.z;
    EXPECT_NEAR(a.raster.y - 180.0, b.raster.y - 180.0, 2e-3 * std::abs(b.raster.y - 180.0)) << p.z;
    EXPECT_GT((a.raster.x - 320.0) * p.x, 0.0);  // upright: +X right, +Y up
    EXPECT_LT((a.raster.y - 180.0) * p.y, 0.0);
  }
}

// unproject then project returns the raster position, for every model and
// any point along the ray (the chief ray images all of them there).
TEST(Projection, RoundTripEveryModel) {
  const FilmGeometry film = test::testFilm();
  const ParaxialData paraxial = computeParaxial(library("wide-22mm"));
  std::vector<std::unique_ptr<Camera>> cameras;
  cameras.push_back(std::make_unique<PinholeCamera>(Transform(), film, 0.9));
  cameras.push_back(std::make_unique<ThinLensCamera>(Transform(), film, thin(3.0)));
  cameras.push_back(
      std::make_unique<ThickLensCamera>(Transform(), film, thickLensFromParaxial(paraxial, 4.0, 1.0)));
  for (const char* name : {"dgauss-50mm", "wide-22mm", "fisheye-10mm"})
    cameras.push_back(fullLens(library(name), 2.0, true));
  for (const auto& cam : cameras)
    for (const Vec2d raster :
         {Vec2d{320.0, 180.0}, Vec2d{0.5, 0.5}, Vec2d{600.25, 20.75}, Vec2d{100.0, 340.0}}) {
      const ProjectedRay ray = cam->unprojectRaster(raster, 550.0);
      if (ray.visibility == Visibility::Blocked) {
        // The fisheye's corners lie outside its image circle.
        EXPECT_NE(cam->describe().find("fisheye"), std::string::npos) << cam->describe();
        continue;
      }
      EXPECT_EQ(ray.visibility, Visibility::Visible);
      EXPECT_NEAR(length(ray.direction), 1.0, 1e-12);
      EXPECT_LT(ray.direction.z, 0.0);
      for (const double along : {0.5, 3.0, 40.0}) {
        const ProjectedPoint p = cam->projectCameraPoint(ray.origin + ray.direction * along, 550.0);
        EXPECT_EQ(p.visibility, Visibility::Visible) << cam->describe();
        EXPECT_NEAR(p.raster.x, raster.x, 1e-6) << cam->describe() << " along " << along;
        EXPECT_NEAR(p.raster.y, raster.y, 1e-6) << cam->describe() << " along " << along;
      }
    }
}

// Shifted and tilted films (--shift, --tilt): the projection lands where the
// camera's own rendering ray through the pupil's centre (the chief ray)
// meets the point: the pinhole shifted, the thin and thick lens shifted and
// tilted about a slanted axis; the full lens shifted, a point in focus from
// three aperture samples; and every model's round trip with movements.
TEST(Projection, ShiftedAndTiltedFilmsFollowTheirRays) {
  const FilmGeometry film = test::testFilm();
  LensMovements shift;
  shift.shiftMm = {3.0, -2.0};
  LensMovements tilt = shift;
  tilt.tiltDegrees = 6.0;
  tilt.tiltAxisDegrees = 30.0;
  const PinholeCamera pinhole(Transform(), film, 0.9, {}, shift);
  ThinLensParams thinTilted = thin(2.0);
  thinTilted.movements = tilt;
  const ThinLensCamera thinLens(Transform(), film, thinTilted);
  const ParaxialData paraxial = computeParaxial(test::lectureDoubleGauss(0.5));
  ThickLensParams thickTilted = thickLensFromParaxial(paraxial, 2.0, 1.5);
  thickTilted.movements = tilt;
  const ThickLensCamera thickLens(Transform(), film, thickTilted);
  for (const Camera* cam : std::initializer_list<const Camera*>{&pinhole, &thinLens, &thickLens})
    for (const Vec3d p : {Vec3d{0.1, -0.05, -1.5}, Vec3d{-0.08, 0.04, -0.6}, Vec3d{0.5, 0.3, -8.0}}) {
      const ProjectedPoint q = cam->projectCameraPoint(p, kD);
      ASSERT_EQ(q.visibility, Visibility::Visible) << cam->describe() << " " << p.z;
      const std::optional<Vec2d> rendered = test::imageOf(*cam, p, {0.5, 0.5}, q.raster);
      ASSERT_TRUE(rendered) << cam->describe();
      EXPECT_NEAR(rendered->x, q.raster.x, 2e-3) << cam->describe() << " " << p.z;
      EXPECT_NEAR(rendered->y, q.raster.y, 2e-3) << cam->describe() << " " << p.z;
      // Not the unmoved film's image: the movement counts.
      const ProjectedPoint plain = PinholeCamera(Transform(), film, 0.9).projectCameraPoint(p, kD);
      if (cam == &pinhole) {
        EXPECT_GT(std::abs(q.raster.x - plain.raster.x), 10.0);
      }
    }

  Warnings warnings;
  LensCameraParams lp;
  lp.fNumber = 4.0;
  lp.focusMetres = 2.0;
  lp.movements = shift;
  const LensCamera lens(Transform(), film, library("dgauss-50mm"), lp, Exposure{}, warnings);
  // On the plane of focus (2 m from the entrance pupil) every aperture sample meets the same film point.
  const Vec3d inFocus{0.15, 0.08, -2.0};
  const ProjectedPoint q = lens.projectCameraPoint(inFocus, kD);
  ASSERT_EQ(q.visibility, Visibility::Visible);
  for (const Vec2d aperture : {Vec2d{0.45, 0.55}, Vec2d{0.35, 0.62}, Vec2d{0.62, 0.4}}) {
    const std::optional<Vec2d> rendered = test::imageOf(lens, inFocus, aperture, q.raster);
    ASSERT_TRUE(rendered) << aperture.x << " at " << q.raster.x << ", " << q.raster.y;
    EXPECT_NEAR(rendered->x, q.raster.x, 0.05) << aperture.x;
    EXPECT_NEAR(rendered->y, q.raster.y, 0.05) << aperture.x;
  }
  const ProjectedPoint unshifted = fullLens(library("dgauss-50mm"), 2.0)->projectCameraPoint(inFocus, kD);
  // 3 mm right and 2 mm down on the film: the picture moves 3 mm left and 2 mm down... in pixels of 36/640
  // mm.
  EXPECT_NEAR(q.raster.x - unshifted.raster.x, -3.0 / (36.0 / 640.0), 0.5);

  lp.movements = tilt;
  const LensCamera tiltedLens(Transform(), film, library("dgauss-50mm"), lp, Exposure{}, warnings);
  for (const Camera* cam :
       std::initializer_list<const Camera*>{&pinhole, &thinLens, &thickLens, &lens, &tiltedLens})
    for (const Vec2d raster : {Vec2d{320.0, 180.0}, Vec2d{40.5, 30.5}, Vec2d{600.25, 320.75}}) {
      const ProjectedRay ray = cam->unprojectRaster(raster, kD);
      ASSERT_EQ(ray.visibility, Visibility::Visible) << cam->describe();
      for (const double along : {0.7, 5.0}) {
        const ProjectedPoint p = cam->projectCameraPoint(ray.origin + ray.direction * along, kD);
        EXPECT_NEAR(p.raster.x, raster.x, 1e-6) << cam->describe() << " along " << along;
        EXPECT_NEAR(p.raster.y, raster.y, 1e-6) << cam->describe() << " along " << along;
      }
    }
}

TEST(Projection, WorldSpaceThroughThePoseAndThreadSafe) {
  const Transform pose = Transform::lookAt({1.0, 2.0, 3.0}, {0.0, 0.5, -1.0}, {0.0, 1.0, 0.0});
  const auto cam = fullLens(library("dgauss-50mm"), 3.0, false, pose);
  const Vec3d world{0.3, 0.7, -1.5};
  const ProjectedPoint a = cam->project(world, kD);
  const ProjectedPoint b = cam->projectCameraPoint(pose.inverse().point(world), kD);
  EXPECT_EQ(a.raster.x, b.raster.x);
  EXPECT_EQ(a.raster.y, b.raster.y);
  const ProjectedRay ray = cam->unproject(a.raster, kD);
  const Vec3d toPoint = normalize(world - ray.origin);
  EXPECT_NEAR(dot(toPoint, ray.direction), 1.0, 1e-12);
  // The same bits from many threads at once.
  std::vector<Vec2d> once(2000), parallel(2000);
  const auto pointAt = [](int i) {
    return Vec3d{std::sin(i * 0.37), std::cos(i * 0.11) * 0.5, -2.0 - 0.001 * i};
  };
  for (int i = 0; i < 2000; ++i) once[std::size_t(i)] = cam->project(pointAt(i), 500.0).raster;
  tbb::parallel_for(0, 2000,
                    [&](int i) { parallel[std::size_t(i)] = cam->project(pointAt(i), 500.0).raster; });
  for (std::size_t i = 0; i < once.size(); ++i) {
    EXPECT_EQ(std::memcmp(&once[i], &parallel[i], sizeof(Vec2d)), 0) << i;
  }
}

TEST(Projection, WavelengthMovesTheFullLensImageOnlyWithDispersion) {
  const Vec3d corner{0.6, 0.4, -2.0};
  const auto on = fullLens(library("dgauss-100mm"), 2.0, true);
  const auto off = fullLens(library("dgauss-100mm"), 2.0, false);
  const double shift = on->projectCameraPoint(corner, kWavelengthFNm).raster.x -
                       on->projectCameraPoint(corner, kWavelengthCNm).raster.x;
  EXPECT_GT(std::abs(shift), 0.01);  // lateral colour: a few um, a tenth of a 56 um pixel
  EXPECT_EQ(off->projectCameraPoint(corner, kWavelengthFNm).raster.x,
            off->projectCameraPoint(corner, kWavelengthCNm).raster.x);
}

TEST(Projection, BlockedAndBehindAreFlagged) {
  // A 36 x 24 mm frame on the fisheye: its corners lie beyond the chief rays' reach.
  FilmGeometry film{600, 400, 36.0, 24.0};
  const auto cam = fullLens(library("fisheye-10mm"), 2.0, false, Transform(), film);
  EXPECT_EQ(cam->unprojectRaster({1.0, 1.0}, kD).visibility, Visibility::Blocked);
  EXPECT_EQ(cam->unprojectRaster({300.0, 200.0}, kD).visibility, Visibility::Visible);
  EXPECT_EQ(cam->projectCameraPoint({0.0, 0.0, 0.5}, kD).visibility, Visibility::Behind);
  EXPECT_TRUE(std::isnan(cam->projectCameraPoint({0.0, 0.0, 0.5}, kD).raster.x));
  // 50 degrees up: within the lens's field, above a 36 x 12 mm frame.
  const auto wide = fullLens(library("fisheye-10mm"), 2.0, false, Transform(), {600, 200, 36.0, 12.0});
  const ProjectedPoint up = wide->projectCameraPoint({0.0, std::tan(50.0 * kPi / 180.0), -1.0}, kD);
  EXPECT_EQ(up.visibility, Visibility::OutsideFrame);
  EXPECT_LT(up.raster.y, 0.0);
}

}  // namespace
}  // namespace lensrt
