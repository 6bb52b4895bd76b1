// Lens movements (shift and tilt) against closed forms: a shift moves a
// distant point's image by exactly the shift (pinhole, thin lens) or by the
// traced amount (full lens); a level camera's verticals stay parallel; the
// tilted film's plane of focus is the Scheimpflug plane with its hinge line
// at f / sin(tilt); the film's cos factor follows the tilted normal.
#include "camera/lens_movements.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "camera/lens_camera.h"
#include "camera/pinhole_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/paraxial.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

using test::cameraRay;
using test::imageOf;

constexpr double kDeg = kPi / 180.0;

LensMovements shift(double x, double y) {
  LensMovements m;
  m.shiftMm = {x, y};
  return m;
}

LensMovements tilt(double degrees, double axisDegrees = 0.0) {
  LensMovements m;
  m.tiltDegrees = degrees;
  m.tiltAxisDegrees = axisDegrees;
  return m;
}

ThinLensParams thin(double f, double n, double focusM, const LensMovements& m = {}) {
  ThinLensParams p;
  p.focalLengthMm = f;
  p.fNumber = n;
  p.focusMetres = focusM;
  p.movements = m;
  return p;
}

LensCamera fullLens(double fNumber, double focusM, const LensMovements& m = {}) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = fNumber;
  p.focusMetres = focusM;
  p.movements = m;
  return LensCamera(Transform(), test::testFilm(), test::lectureDoubleGauss(0.5), p, Exposure{}, warnings);
}

// The raster position of an upright sensor point (mm from the frame's
// centre), written out from the conventions (x right, y up; raster y down).
Vec2d rasterOfMm(const FilmGeometry& f, Vec2d mm) {
  return {(mm.x / f.sensorWidthMm + 0.5) * f.width, (0.5 - mm.y / f.sensorHeightMm) * f.height};
}

double angleBetween(const Vec3d& a, const Vec3d& b) {
  return std::atan2(length(cross(a, b)), dot(a, b));
}

// ---- The value type ----

TEST(LensMovements, NoneDescribesAsNothing) {
  EXPECT_FALSE(LensMovements{}.any());
  EXPECT_EQ(LensMovements{}.describe(), "");
  EXPECT_EQ(shift(0, 8).describe(), " shift=0,8mm");
  EXPECT_EQ(tilt(4).describe(), " tilt=4deg");
  LensMovements both = tilt(-3.5, 90);
  both.shiftMm = {2, -1};
  EXPECT_EQ(both.describe(), " shift=2,-1mm tilt=-3.5deg tilt-axis=90deg");
  EXPECT_EQ(tilt(0, 90).describe(), "") << "an axis without a tilt does nothing";
}

TEST(LensMovements, ProblemsNameTheValueAndTheLimit) {
  const FilmGeometry film;  // 36 x 24 mm
  EXPECT_FALSE(lensMovementsProblem(shift(36, -24), film));
  EXPECT_FALSE(lensMovementsProblem(tilt(30, -360), film));
  EXPECT_EQ(lensMovementsProblem(shift(40, 0), film).value_or(""),
            "the shift's X (40 mm) must lie within +-36 mm (the sensor's width)");
  EXPECT_EQ(lensMovementsProblem(shift(0, -30), film).value_or(""),
            "the shift's Y (-30 mm) must lie within +-24 mm (the sensor's height)");
  EXPECT_EQ(lensMovementsProblem(tilt(35), film).value_or(""),
            "the tilt (35 degrees) must lie within +-30 degrees");
  EXPECT_EQ(lensMovementsProblem(tilt(5, 400), film).value_or(""),
            "the tilt axis (400 degrees) must lie within +-360 degrees");
  EXPECT_EQ(lensMovementsProblem(shift(NAN, 0), film).value_or(""), "the shift must be finite");
  EXPECT_EQ(lensMovementsProblem(tilt(INFINITY), film).value_or(""), "the tilt must be finite");
  try {
    const ThinLensCamera cam(Transform(), film, thin(50, 2, 3, tilt(31)));
    FAIL() << "a tilt beyond the limit was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "thin lens: the tilt (31 degrees) must lie within +-30 degrees");
  }
  EXPECT_THROW(PinholeCamera(Transform(), film, 0.7, "", tilt(4)), std::invalid_argument);
}

// offset() and upright() invert each other, the film stays rigid (distances
// in it are kept) and the normal is perpendicular to it.
TEST(LensMovements, MovedFilmIsARigidPlane) {
  LensMovements m = tilt(12, 33);
  m.shiftMm = {3, -5};
  const MovedFilm film(m);
  const std::array<Vec2d, 3> pts{Vec2d{0, 0}, Vec2d{10, 2}, Vec2d{-4, 9}};
  for (const Vec2d& p : pts) {
    const Vec2d back = film.upright(film.offset(p));
    EXPECT_NEAR(back.x, p.x, 1e-12);
    EXPECT_NEAR(back.y, p.y, 1e-12);
    EXPECT_NEAR(dot(film.offset(p) - film.offset(pts[0]), film.normal()), 0.0, 1e-12);
  }
  const Vec3d d = film.offset(pts[1]) - film.offset(pts[2]);
  EXPECT_NEAR(length(d), std::hypot(14.0, -7.0), 1e-12);
  EXPECT_NEAR(length(film.normal()), 1.0, 1e-15);
}

// ---- Shift ----

// A distant point at field tangents t images at f t on the unshifted film;
// shifted by s, at f t - s in the frame: the ray from that raster position
// points at it (float rays: to 2e-7 rad, 1e-5 mm on the film).
TEST(LensMovements, ShiftMovesADistantPointsImageByTheShiftPinholeAndThin) {
  const FilmGeometry film = test::testFilm();
  const double yfov = 2.0 * std::atan(0.5 * film.sensorHeightMm / 50.0);  // f = 50 mm
  for (const Vec2d s : {Vec2d{0, 8}, Vec2d{-5, 3}, Vec2d{12, -10}}) {
    const PinholeCamera pinhole(Transform(), film, yfov, "", shift(s.x, s.y));
    const ThinLensCamera thinLens(Transform(), film, thin(50, 2, kInfinity, shift(s.x, s.y)));
    for (const Camera* cam : {static_cast<const Camera*>(&pinhole), static_cast<const Camera*>(&thinLens)})
      for (const Vec2d t : {Vec2d{0, 0}, Vec2d{0.1, 0.2}, Vec2d{-0.25, 0.05}}) {
        const Vec2d raster = rasterOfMm(film, t * 50.0 - s);
        const auto r = cameraRay(*cam, raster, {0.5, 0.5});
        ASSERT_TRUE(r);
        EXPECT_LT(angleBetween(Vec3d(r->direction), {t.x, t.y, -1.0}), 2e-7)
            << cam->describe() << " t=" << t.x << "," << t.y;
      }
  }
}

// Tracing the chief ray of a distant point at field angle theta from the
// scene through the stop's centre (optics library, secant on the entrance
// height) gives its image height h(theta) on the film, distortion included.
// Shifted by s, the camera's ray from the raster position of h - s through
// that chief ray's rear-plane point leaves along theta.
TEST(LensMovements, ShiftMovesADistantPointsImageByTheTracedAmountFullLens) {
  const double sy = 8.0;
  const LensCamera cam = fullLens(4.0, kInfinity, shift(0, sy));
  const LensSystem& lens = cam.lens();
  const int stop = lens.paraxial().stopIndex;
  for (const double degrees : {3.0, 8.0, 14.0}) {
    const double theta = degrees * kDeg;
    const Vec3d dir{0.0, -std::sin(theta), std::cos(theta)};  // light from above, toward the film
    // Rays aimed at height h of the entrance pupil's plane, from 100 mm in front of it.
    const auto origin = [&](double h) { return Vec3d{0.0, h, lens.paraxial().entrancePupilZ} - dir * 100.0; };
    const auto stopHeight = [&](double h) {
      std::vector<Vec3d> path;
      const auto out = lens.traceFromScene({origin(h), dir}, kWavelengthDNm, &path);
      EXPECT_TRUE(out) << "h " << h;
      return out ? path.at(stop).y : 0.0;
    };
    double h0 = 0.0, h1 = 0.1, g0 = stopHeight(h0), g1 = stopHeight(h1);
    for (int i = 0; i < 30 && std::abs(g1) > 1e-12 && g1 != g0; ++i) {
      const double h2 = h1 - g1 * (h1 - h0) / (g1 - g0);
      h0 = h1, g0 = g1, h1 = h2, g1 = stopHeight(h1);
    }
    ASSERT_LT(std::abs(g1), 1e-9);
    const auto chief = lens.traceFromScene({origin(h1), dir});
    ASSERT_TRUE(chief);
    const double toFilm = (cam.filmZ() - chief->origin.z) / chief->direction.z;
    const double imageHeight = -(chief->origin.y + toFilm * chief->direction.y);  // upright
    const double toRear = (lens.rearZ() - chief->origin.z) / chief->direction.z;
    const Vec2d rearPoint{chief->origin.x + toRear * chief->direction.x,
                          chief->origin.y + toRear * chief->direction.y};
    const Vec2d raster = rasterOfMm(cam.film(), {0.0, imageHeight - sy});
    const auto r = cam.traceThrough({float(raster.x), float(raster.y)}, rearPoint);
    ASSERT_TRUE(r) << degrees;
    EXPECT_LT(angleBetween(Vec3d(r->direction), {0.0, std::sin(theta), -std::cos(theta)}), 2e-6)
        << degrees << " deg: traced image height " << imageHeight
        << " mm (f tan = " << lens.paraxial().efl * std::tan(theta) << ")";
  }
}

// A level camera with a rising front: two vertical lines of a building stay
// vertical in the picture (the image x of their points varies by under
// 0.1 px from the bottom to the top of the frame). The camera pitched up by
// atan(shift / f) instead, for about the same view, makes them converge
// (the control: the measure sees it).
double verticalsLean(const Camera& cam) {
  double worst = 0.0;
  for (const double x : {-2.0, 2.5}) {
    double lo = kInfinity, hi = -kInfinity;
    for (double y = -1.0; y <= 6.0; y += 0.5) {
      const Vec3d p = cam.worldFromCamera().inverse().point(Vec3d{x, y, -9.0});  // world to camera space
      const auto img = imageOf(cam, p, {0.5, 0.5}, {cam.film().width / 2.0, cam.film().height / 2.0});
      if (!img) continue;
      if (img->y < 0 || img->y > cam.film().height) continue;  // in the frame
      lo = std::min(lo, img->x);
      hi = std::max(hi, img->x);
    }
    worst = std::max(worst, hi - lo);
  }
  return worst;
}

TEST(LensMovements, ShiftKeepsVerticalsParallel) {
  const FilmGeometry film = test::testFilm();
  const double f = 35.0, sy = 8.0;
  const double yfov = 2.0 * std::atan(0.5 * film.sensorHeightMm / f);
  const ParaxialData para = computeParaxial(test::lectureDoubleGauss(0.35));
  ThickLensParams thick = thickLensFromParaxial(para, 8.0, 9.0);
  thick.movements = shift(0, sy);
  const PinholeCamera pinhole(Transform(), film, yfov, "", shift(0, sy));
  const ThinLensCamera thinLens(Transform(), film, thin(f, 8, 9.0, shift(0, sy)));
  const ThickLensCamera thickLens(Transform(), film, thick);
  for (const Camera* cam : {static_cast<const Camera*>(&pinhole), static_cast<const Camera*>(&thinLens),
                            static_cast<const Camera*>(&thickLens)}) {
    const double lean = verticalsLean(*cam);
    EXPECT_LT(lean, 0.1) << cam->describe();
    std::printf("%s: verticals lean %.2g px\n", cam->describe().c_str(), lean);
  }
  const double pitch = std::atan(sy / f);
  const Transform pitched = Transform::rotateQuaternion(std::sin(pitch / 2), 0, 0, std::cos(pitch / 2));
  const PinholeCamera tiltedUp(pitched, film, yfov);
  const double lean = verticalsLean(tiltedUp);
  std::printf("pinhole pitched up %.3g deg, no shift: verticals lean %.3g px\n", pitch / kDeg, lean);
  EXPECT_GT(lean, 5.0);
}

// ---- Tilt ----

// Where rays meet: the least-squares point closest to all the lines.
Vec3d closestPoint(const std::vector<Ray>& rays) {
  // sum (I - d d^T) (x - o) = 0.
  std::array<std::array<double, 3>, 3> a{};
  std::array<double, 3> b{};
  for (const Ray& r : rays) {
    const Vec3d o(r.origin), d = normalize(Vec3d(r.direction));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double m = (i == j ? 1.0 : 0.0) - d[i] * d[j];
        a[i][j] += m;
        b[i] += m * o[j];
      }
  }
  // Cramer's rule.
  const auto det = [](const std::array<std::array<double, 3>, 3>& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  Vec3d x;
  for (int k = 0; k < 3; ++k) {
    auto m = a;
    for (int i = 0; i < 3; ++i) m[i][k] = b[i];
    x[k] = det(m) / d;
  }
  return x;
}

// A plane n.x = c.
struct Plane {
  Vec3d n;
  double c = 0.0;
};

double det3(const std::array<std::array<double, 3>, 3>& m) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The least-squares plane z = a x + b y + c through the points (the planes
// here face the camera, so z is a function of x and y), by the normal
// equations and Cramer's rule.
Plane fitPlane(const std::vector<Vec3d>& pts) {
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> r{};
  for (const Vec3d& p : pts) {
    const std::array<double, 3> row{p.x, p.y, 1.0};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] += row[i] * row[j];
      r[i] += row[i] * p.z;
    }
  }
  std::array<double, 3> abc{};
  for (int k = 0; k < 3; ++k) {
    auto mk = m;
    for (int i = 0; i < 3; ++i) mk[i][k] = r[i];
    abc[k] = det3(mk) / det3(m);
  }
  // z - a x - b y = c.
  const Vec3d n{-abc[0], -abc[1], 1.0};
  const double len = length(n);
  return {n / len, abc[2] / len};
}

// The line where planes n1.x = c1 and n2.x = c2 meet: its point closest to
// the origin (in the span of the normals).
Vec3d closestOnMeet(const Plane& p, const Plane& q) {
  const double nn = dot(p.n, q.n);
  const double det = 1.0 - nn * nn;
  const double a = (p.c - nn * q.c) / det, b = (q.c - nn * p.c) / det;
  return p.n * a + q.n * b;
}

// The conjugate (in camera space, mm) of a raster point: where the camera's
// rays from it through `lensSamples` meet, and how far they pass from it.
struct Conjugate {
  Vec3d point;
  double spread = 0.0;  // largest miss (mm)
};
Conjugate conjugate(const std::vector<Ray>& raysMetres) {
  std::vector<Ray> rays;
  for (Ray r : raysMetres) {
    r.origin = r.origin * 1000.0f;
    rays.push_back(r);
  }
  Conjugate c{closestPoint(rays)};
  for (const Ray& r : rays) {
    const Vec3d o(r.origin), d = normalize(Vec3d(r.direction));
    const Vec3d v = c.point - o;
    c.spread = std::max(c.spread, length(v - d * dot(v, d)));
  }
  return c;
}

struct TiltCase {
  double tiltDegrees, axisDegrees;
};
constexpr std::array kTilts{TiltCase{4, 0}, TiltCase{-7, 0}, TiltCase{10, 90}, TiltCase{6, 35}};

// The expected lines, from the geometry: the film (through the pivot at v
// behind the principal plane, tilted by `tilt` about the axis line)
// meets the (rear) principal plane in the Scheimpflug line, whose point
// nearest the axis lies v / tan(tilt) from it, toward where the film's
// far side is (the picture's bottom for axis 0: (sin a, -cos a) in camera
// x, y for axis angle a); the plane through the (front) principal point
// parallel to the film meets the front focal plane in the hinge line,
// f / tan(tilt) from the axis the same way, f in front: J = f / sin(tilt).
Vec3d scheimpflugPoint(const TiltCase& t, double v, double principalZ) {
  const double k = v / std::tan(t.tiltDegrees * kDeg), a = t.axisDegrees * kDeg;
  return {k * std::sin(a), -k * std::cos(a), principalZ};
}
Vec3d hingePoint(const TiltCase& t, double f, double principalZ) {
  const double k = f / std::tan(t.tiltDegrees * kDeg), a = t.axisDegrees * kDeg;
  return {k * std::sin(a), -k * std::cos(a), principalZ - f};
}

// The conjugates of film points over the frame (rays through 16 lens
// samples each) lie on one plane; it meets the lens plane in the
// Scheimpflug line and the front focal plane in the hinge line.
struct FocusPlane {
  Plane plane;
  double worstSpread = 0.0;    // of a film point's rays about their conjugate (mm)
  double worstOffPlane = 0.0;  // of a conjugate from the plane (mm)
};
FocusPlane focusPlane(const Camera& cam) {
  const FilmGeometry& f = cam.film();
  std::vector<Vec3d> points;
  FocusPlane out;
  SplitMix64 rng(17);
  for (const Vec2d frac : {Vec2d{0.1, 0.1}, Vec2d{0.9, 0.15}, Vec2d{0.5, 0.9}, Vec2d{0.3, 0.6},
                           Vec2d{0.75, 0.7}, Vec2d{0.5, 0.5}, Vec2d{0.15, 0.85}}) {
    std::vector<Ray> rays;
    for (int i = 0; i < 16; ++i) {
      const auto r = cameraRay(cam, {frac.x * f.width, frac.y * f.height}, {rng.uniform(), rng.uniform()});
      if (r) rays.push_back(*r);
    }
    EXPECT_GE(rays.size(), 8u);
    const Conjugate c = conjugate(rays);
    out.worstSpread = std::max(out.worstSpread, c.spread);
    points.push_back(c.point);
  }
  out.plane = fitPlane(points);
  for (const Vec3d& p : points)
    out.worstOffPlane = std::max(out.worstOffPlane, std::abs(dot(out.plane.n, p) - out.plane.c));
  return out;
}

void expectNear(const Vec3d& got, const Vec3d& want, double tolerance, const char* what) {
  EXPECT_LT(length(got - want), tolerance)
      << what << ": got (" << got.x << ", " << got.y << ", " << got.z << "), want (" << want.x << ", "
      << want.y << ", " << want.z << ")";
}

// The thin lens is an exact collineation: every ray from a film point meets
// at its conjugate (float rays: to a micrometre at metres), the conjugates
// lie on one plane, and the lines are where the closed forms put them
// (to 1e-5 of J: float rays over metres).
TEST(LensMovements, ThinLensTiltFollowsScheimpflugAndHinge) {
  const double f = 50.0, focusMm = 3000.0;
  const double v = f * focusMm / (focusMm - f);
  for (const TiltCase& t : kTilts) {
    SCOPED_TRACE(t.tiltDegrees);
    SCOPED_TRACE(t.axisDegrees);
    const ThinLensCamera cam(Transform(), test::testFilm(),
                             thin(f, 2.8, focusMm / 1000.0, tilt(t.tiltDegrees, t.axisDegrees)));
    const FocusPlane fp = focusPlane(cam);
    const double J = f / std::abs(std::sin(t.tiltDegrees * kDeg));
    EXPECT_LT(fp.worstSpread, 1e-6 * focusMm * 10) << "mm: the rays of a film point meet at one point";
    EXPECT_LT(fp.worstOffPlane, 1e-5 * focusMm * 10) << "mm: the conjugates lie on one plane";
    const Vec3d hinge = closestOnMeet(fp.plane, {{0, 0, 1}, -f});
    expectNear(hinge, hingePoint(t, f, 0.0), 1e-5 * J, "hinge line");
    EXPECT_NEAR(length(hinge), J, 1e-5 * J) << "J = f / sin(tilt)";
    expectNear(closestOnMeet(fp.plane, {{0, 0, 1}, 0.0}), scheimpflugPoint(t, v, 0.0), 1e-5 * J,
               "Scheimpflug line");
    // The plane of focus still crosses the axis at the focus distance.
    EXPECT_NEAR(fp.plane.c / fp.plane.n.z, -focusMm, 1e-5 * focusMm);
    std::printf("thin lens tilt %g deg axis %g: J %.6f mm (f / sin = %.6f), rays meet within %.2g mm\n",
                t.tiltDegrees, t.axisDegrees, length(hinge), J, fp.worstSpread);
  }
}

// The thick lens is a collineation too, about its principal planes: the
// same lines, measured from H (the Scheimpflug line in the plane of H, to
// which the film's line at H' maps at unit magnification).
TEST(LensMovements, ThickLensTiltFollowsScheimpflugAndHinge) {
  const ParaxialData para = computeParaxial(test::lectureDoubleGauss(0.5));
  for (const TiltCase& t : kTilts) {
    SCOPED_TRACE(t.tiltDegrees);
    ThickLensParams p = thickLensFromParaxial(para, 2.8, 3.0);
    p.movements = tilt(t.tiltDegrees, t.axisDegrees);
    const ThickLensCamera cam(Transform(), test::testFilm(), p);
    const double f = p.focalLengthMm, v = cam.imageDistance();
    const double hZ = p.frontPrincipalZ - p.entrancePupilZ;  // H in camera space (mm)
    const FocusPlane fp = focusPlane(cam);
    const double J = f / std::abs(std::sin(t.tiltDegrees * kDeg));
    EXPECT_LT(fp.worstSpread, 1e-2);
    EXPECT_LT(fp.worstOffPlane, 0.1);
    const Vec3d hinge = closestOnMeet(fp.plane, {{0, 0, 1}, hZ - f});
    expectNear(hinge, hingePoint(t, f, hZ), 1e-5 * J, "hinge line");
    expectNear(closestOnMeet(fp.plane, {{0, 0, 1}, hZ}), scheimpflugPoint(t, v, hZ), 1e-5 * J,
               "Scheimpflug line");
    std::printf("thick lens tilt %g deg axis %g: J %.6f mm from H (f / sin = %.6f)\n", t.tiltDegrees,
                t.axisDegrees, length(hinge - Vec3d{0, 0, hZ}), J);
  }
}

// The full lens is no collineation (field curvature, astigmatism,
// distortion), so its plane of sharp focus is only nearly a plane and the
// rule holds to first order. Conjugates from narrow bundles (2 mm on the
// rear plane around the chief ray toward the paraxial exit pupil) of film
// points within +-6 mm of the centre; the hinge line then lies within 4% of
// J of where the rule puts it, measured from the paraxial H (measured:
// 1.6% at 4 deg, 2.5% at 8 deg; the conjugates stray from their plane by
// 10-20 mm at 3 m, the lens's field curvature and astigmatism).
TEST(LensMovements, FullLensTiltFollowsTheHingeRuleApproximately) {
  for (const TiltCase& t : {TiltCase{4, 0}, TiltCase{8, 90}}) {
    SCOPED_TRACE(t.tiltDegrees);
    const LensCamera cam = fullLens(2.0, 3.0, tilt(t.tiltDegrees, t.axisDegrees));
    const ParaxialData& para = cam.lens().paraxial();
    const double f = para.efl;
    const double hZ = para.frontPrincipalZ - cam.entrancePupilZ();
    const FilmGeometry& film = cam.film();
    // The film point of an upright position, from the conventions: tilted
    // about the axis line through the pivot, inverted.
    const double a = t.axisDegrees * kDeg, tl = t.tiltDegrees * kDeg;
    const Vec2d axis{std::cos(a), std::sin(a)}, across{-std::sin(a), std::cos(a)};
    std::vector<Vec3d> points;
    for (const Vec2d up : {Vec2d{-6, -6}, Vec2d{6, -5}, Vec2d{0, 6}, Vec2d{3, 1}, Vec2d{-3, 3}, Vec2d{0, 0},
                           Vec2d{6, 5}, Vec2d{-6, 2}, Vec2d{2, -6}}) {
      const double wa = up.x * axis.x + up.y * axis.y, wb = up.x * across.x + up.y * across.y;
      const Vec2d lateral = axis * wa + across * (wb * std::cos(tl));
      const Vec3d p{-lateral.x, -lateral.y, cam.filmZ() - wb * std::sin(tl)};
      const Vec3d toPupil = Vec3d{0, 0, para.exitPupilZ} - p;
      const Vec3d c = p + toPupil * ((cam.lens().rearZ() - p.z) / toPupil.z);
      const Vec2d raster = rasterOfMm(film, up);
      std::vector<Ray> rays;
      for (const Vec2d d : {Vec2d{0, 0}, Vec2d{1, 0}, Vec2d{-1, 0}, Vec2d{0, 1}, Vec2d{0, -1}}) {
        const auto r = cam.traceThrough({float(raster.x), float(raster.y)}, {c.x + d.x, c.y + d.y});
        ASSERT_TRUE(r);
        rays.push_back(*r);
      }
      points.push_back(conjugate(rays).point);
    }
    const Plane best = fitPlane(points);
    double off = 0.0;
    for (const Vec3d& p : points) off = std::max(off, std::abs(dot(best.n, p) - best.c));
    const double J = f / std::sin(std::abs(tl));
    const Vec3d hinge = closestOnMeet(best, {{0, 0, 1}, hZ - f});
    std::printf(
        "full lens tilt %g deg axis %g: hinge %.1f mm from H (f / sin = %.1f), off by %.1f mm; "
        "conjugates off the plane by %.2g mm\n",
        t.tiltDegrees, t.axisDegrees, length(hinge - Vec3d{0, 0, hZ}), J,
        length(hinge - hingePoint(t, f, hZ)), off);
    expectNear(hinge, hingePoint(t, f, hZ), 0.04 * J, "hinge line");
  }
}

// The perspective centre stays the entrance pupil's: the thick lens's ray
// from any film point of a tilted, shifted film through the exit pupil's
// centre (the chief ray) leaves through the entrance pupil's centre, the
// camera origin (the two pupils are conjugate), to float precision.
TEST(LensMovements, ThickLensChiefRaysPassTheEntrancePupilCentre) {
  ThickLensParams p = thickLensFromParaxial(computeParaxial(test::lectureDoubleGauss(0.5)), 2.8, 3.0);
  p.movements = tilt(8, 30);
  p.movements.shiftMm = {4, -3};
  const ThickLensCamera cam(Transform(), test::testFilm(), p);
  for (const Vec2d raster : {Vec2d{10, 10}, Vec2d{630, 20}, Vec2d{320, 180}, Vec2d{100, 350}}) {
    const auto r = cameraRay(cam, raster, {0.5, 0.5});
    ASSERT_TRUE(r);
    const Vec3d o(r->origin), d = normalize(Vec3d(r->direction));
    const Vec3d miss = o - d * dot(o, d);  // the line's nearest point to the origin
    EXPECT_LT(length(miss) * 1000.0, 1e-4) << "mm from the entrance pupil's centre, raster " << raster.x;
  }
}

// The flare light pass finds where a ray from the lens meets the moved film
// (LensCamera::rasterOfFilmHit): the raster position whose film point, from
// the conventions, that ray reaches.
TEST(LensMovements, FullLensFindsTheRasterOfAFilmHit) {
  LensMovements m = tilt(6, 120);
  m.shiftMm = {-2, 5};
  const LensCamera cam = fullLens(2.8, 3.0, m);
  const double a = 120 * kDeg, tl = 6 * kDeg;
  const Vec2d axis{std::cos(a), std::sin(a)}, across{-std::sin(a), std::cos(a)};
  for (const Vec2d raster : {Vec2d{10.5, 20.25}, Vec2d{600, 300}, Vec2d{320, 180}}) {
    const Vec2d up = Vec2d{(raster.x / 640 - 0.5) * 36, (0.5 - raster.y / 360) * 20.25} + m.shiftMm;
    const double wa = up.x * axis.x + up.y * axis.y, wb = up.x * across.x + up.y * across.y;
    const Vec2d lateral = axis * wa + across * (wb * std::cos(tl));
    const Vec3d filmPoint{-lateral.x, -lateral.y, cam.filmZ() - wb * std::sin(tl)};
    const Vec3d dir = normalize(Vec3d{0.3, -0.2, 1.0});
    const Vec2d got = cam.rasterOfFilmHit({filmPoint - dir * 20.0, dir});
    EXPECT_NEAR(got.x, raster.x, 1e-9);
    EXPECT_NEAR(got.y, raster.y, 1e-9);
  }
}

// The film records E = integral of L cos(th_film) cos(th_lens) / d^2: at the
// frame's centre the chief ray runs along the axis, so the tilted film's
// normal takes cos(tilt) of it (and the lens side keeps its cos of 1):
// E_tilted / E = cos(tilt). Thin and thick lens exactly (their weight
// follows the chief ray); the full lens in expectation over its pupil
// (symmetric about the axis, so the normal's sideways part averages out),
// 400k samples each: 0.25% (the cos of 10 deg is 1.5% less than 1).
TEST(LensMovements, TiltedFilmRecordsCosTiltAtTheCentre) {
  const FilmGeometry film = test::testFilm();
  const Vec2d centre{film.width / 2.0, film.height / 2.0};
  const double t = 10.0;
  const auto weight = [&](const Camera& cam, Vec2d lens) {
    CameraSample s;
    s.film = {float(centre.x), float(centre.y)};
    s.lens = {float(lens.x), float(lens.y)};
    const auto r = cam.generateRay(s);
    return r ? double(r->weight) : 0.0;
  };
  {
    const ThinLensCamera flat(Transform(), film, thin(50, 2, 3)),
        tilted(Transform(), film, thin(50, 2, 3, tilt(t, 20)));
    EXPECT_NEAR(weight(tilted, {0.3, 0.7}) / weight(flat, {0.3, 0.7}), std::cos(t * kDeg), 1e-6);
  }
  {
    ThickLensParams p = thickLensFromParaxial(computeParaxial(test::lectureDoubleGauss(0.5)), 2.8, 3.0);
    const ThickLensCamera flat(Transform(), film, p);
    p.movements = tilt(t, 20);
    const ThickLensCamera tilted(Transform(), film, p);
    EXPECT_NEAR(weight(tilted, {0.3, 0.7}) / weight(flat, {0.3, 0.7}), std::cos(t * kDeg), 1e-6);
  }
  const LensCamera flat = fullLens(2.0, 3.0), tilted = fullLens(2.0, 3.0, tilt(t, 20));
  double sumFlat = 0.0, sumTilted = 0.0;
  const int n = 400'000;
  SplitMix64 rng(23);
  for (int i = 0; i < n; ++i) {
    const Vec2d u{rng.uniform(), rng.uniform()};
    sumFlat += weight(flat, u);
    sumTilted += weight(tilted, u);
  }
  std::printf("full lens: E(tilt %g deg) / E = %.5f (cos = %.5f)\n", t, sumTilted / sumFlat,
              std::cos(t * kDeg));
  EXPECT_NEAR(sumTilted / sumFlat, std::cos(t * kDeg), 0.0025);
}

// The shifted full lens reaches its frame's far corner: the bounds cover
// the moved film out to its farthest point. Shifted by (3, 2) mm, the top
// right corner lies 24.2 mm from the axis, beyond the unmoved frame's half
// diagonal (20.7 mm), where bounds for it would give no rays; inside the
// lens's image circle, most of its rays pass (89% measured).
TEST(LensMovements, ShiftedFullLensSamplesTheWholeFrame) {
  const LensCamera cam = fullLens(4.0, kInfinity, shift(3, 2));
  const FilmGeometry& film = cam.film();
  int passed = 0;
  SplitMix64 rng(3);
  for (int i = 0; i < 400; ++i) {
    CameraSample s;
    s.film = {float(film.width - 0.5), 0.5f};
    s.lens = {float(rng.uniform()), float(rng.uniform())};
    passed += cam.generateRay(s).has_value();
  }
  EXPECT_GT(passed, 300);
}

// Without movements nothing changes: the descriptions read as before.
TEST(LensMovements, NoMovementsLeaveDescriptionsAlone) {
  const ThinLensCamera cam(Transform(), test::testFilm(), thin(50, 2, 3));
  EXPECT_EQ(cam.describe(), "thin lens f=50mm f/2 focus=3m aperture=round");
  const ThinLensCamera moved(Transform(), test::testFilm(), thin(50, 2, 3, shift(0, 8)));
  EXPECT_EQ(moved.describe(), "thin lens f=50mm f/2 focus=3m aperture=round shift=0,8mm");
  EXPECT_EQ(moved.info().movements.shiftMm.y, 8.0);
}

}  // namespace
}  // namespace lensrt
