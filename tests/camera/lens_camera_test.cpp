// The full lens: focus, blur and relative illumination against paraxial
// optics and an independent brute-force integration.
#include "camera/lens_camera.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "camera/film_mapping.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "core/error.h"
#include "optics/paraxial.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

using test::cameraRay;
using test::imageOf;
using test::pointAtZ;

LensCamera makeLens(double fNumber, double focusM, ApertureShape shape = {}) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = fNumber;
  p.focusMetres = focusM;
  p.aperture = shape;
  return LensCamera(Transform(), test::testFilm(), test::lectureDoubleGauss(0.5), p, Exposure{}, warnings);
}

// Images (raster) of a camera-space point through `samples` points of the
// rear-vertex plane drawn from the pupil bounds of the film point at `guess`
// (those the lens blocks are skipped).
std::vector<Vec2d> imagesOf(const LensCamera& cam, const Vec3d& p, Vec2d guess, int samples,
                            std::uint64_t seed) {
  SplitMix64 rng(seed);
  const Vec2d up = uprightSensorPointMm(cam.film(), {float(guess.x), float(guess.y)});
  std::vector<Vec2d> out;
  for (int i = 0; i < samples; ++i) {
    const auto s = cam.bounds().sample({-up.x, -up.y}, {rng.uniform(), rng.uniform()});
    if (!s) continue;
    const Vec2d pupil{s->point.x, s->point.y};
    const auto rayAt = [&](Vec2d raster) {
      return cam.traceThrough({float(raster.x), float(raster.y)}, pupil);
    };
    if (const auto img = imageOf(rayAt, p, guess)) out.push_back(*img);
  }
  return out;
}

constexpr double kPixelMm = 36.0 / 640.0;

// The film-centre rays lie in planes through the camera's Z axis (the
// optical axis); near-axis (paraxial) ones cross it at the focus distance,
// wider ones nearer, by the lens's spherical aberration (<= 15% at f/4).
double axisCrossing(const Ray& r) {
  const Vec3d o(r.origin), d(r.direction);
  const double radial = std::hypot(d.x, d.y);
  const double t = -(o.x * d.x + o.y * d.y) / (radial * radial);  // closest approach
  return -(o.z + t * d.z);
}

TEST(LensCamera, CentreRaysCrossTheAxisAtTheFocusDistance) {
  const LensCamera cam = makeLens(4, 2.0);
  SplitMix64 rng(1);
  int passed = 0;
  for (int i = 0; i < 200; ++i) {
    const auto r = cameraRay(cam, {320, 180}, {rng.uniform(), rng.uniform()});
    if (!r) continue;
    ++passed;
    const Vec3d o(r->origin), d(r->direction);
    EXPECT_LT(std::abs(o.x * d.y - o.y * d.x) / std::hypot(d.x, d.y), 1e-6) << "metres from the axis";
    EXPECT_NEAR(axisCrossing(*r), 2.0, 0.3);
  }
  EXPECT_GT(passed, 100);
  const double small = 0.01 * cam.lens().rearApertureRadius();
  for (const Vec2d q : {Vec2d{small, 0}, Vec2d{0, -small}, Vec2d{-0.7 * small, 0.7 * small}}) {
    const auto r = cam.traceThrough({320, 180}, q);
    ASSERT_TRUE(r);
    EXPECT_NEAR(axisCrossing(*r), 2.0, 0.01);
  }
  const auto chief = cam.traceThrough({320, 180}, {0, 0});
  ASSERT_TRUE(chief);
  EXPECT_NEAR(chief->direction.z, -1.0, 1e-7);
}

// An on-axis point at the focus distance lands on one film point (within
// the lens's residual spherical aberration) at f/8: well inside a pixel.
TEST(LensCamera, PointAtTheFocusDistanceIsSharp) {
  for (const double focusM : {1.0, 3.0}) {
    const LensCamera cam = makeLens(8, focusM);
    const auto pts = imagesOf(cam, {0, 0, -focusM}, {320, 180}, 200, 2);
    ASSERT_GT(pts.size(), 100u);
    const double spotUm = test::spread(pts) * kPixelMm * 1e3;
    RecordProperty("spot_um_at_" + std::to_string(int(focusM)) + "m", std::to_string(spotUm));
    EXPECT_LT(spotUm, 1.5 * kPixelMm * 1e3) << "spot diameter in um";
    EXPECT_LT(spotUm, 15.0);
  }
}

// Off axis too: a point of the focus plane 10 cm off axis.
TEST(LensCamera, OffAxisPointInTheFocusPlaneIsSharpAtF8) {
  const LensCamera cam = makeLens(8, 2.0);
  const auto pts = imagesOf(cam, {0.1, 0.05, -2.0}, {330, 175}, 200, 3);
  ASSERT_GT(pts.size(), 100u);
  EXPECT_LT(test::spread(pts), 1.5);
}

// A point at twice the focus distance blurs into the cone from its image
// through the exit pupil: diameter D_xp |film - z'| / (z' - z_xp), paraxially.
TEST(LensCamera, PointAtTwiceTheFocusDistanceSpreadsAsPredicted) {
  const double focusM = 1.5, n = 8;  // at f/8 the spherical aberration adds little
  const LensCamera cam = makeLens(n, focusM);
  const ParaxialData& p = cam.lens().paraxial();
  const Conjugate c2 = paraxialConjugate(p, 2 * focusM * 1e3);
  const double predictedMm =
      p.exitPupilDiameter * std::abs(cam.filmZ() - c2.imageZ) / (c2.imageZ - p.exitPupilZ);
  const auto pts = imagesOf(cam, {0, 0, -2 * focusM}, {320, 180}, 600, 4);
  ASSERT_GT(pts.size(), 300u);
  const double measuredMm = test::spread(pts) * kPixelMm;
  EXPECT_NEAR(measuredMm, predictedMm, 0.05 * predictedMm);
}

// Relative illumination E(r)/E(0): the camera's estimator (bounds-sampled)
// against brute force, uniform over a square on the rear-vertex plane that
// holds every ray the rear element can pass, traced without any bounds.
TEST(LensCamera, RelativeIlluminationMatchesBruteForce) {
  const LensCamera cam = makeLens(2.8, kInfinity);
  const FilmGeometry film = test::testFilm();
  const double halfDiag = sensorHalfDiagonalMm(film);
  const LensSystem& lens = cam.lens();
  const double planeZ = lens.rearZ(), filmZ = cam.filmZ();
  // Rays through the rear rim cross the plane within a few per cent of its
  // radius (the sag is small next to the film distance); checked below.
  const double half = 1.3 * lens.rearApertureRadius() + 0.2 * halfDiag;
  double farthestPassing = 0;

  std::vector<double> camera, brute, camSigma, bruteSigma;
  for (const double frac : {0.0, 0.4, 0.7, 0.9, 1.0}) {
    // Along the diagonal: raster position of an upright sensor point.
    const double rx = frac * film.sensorWidthMm / 2, ry = frac * film.sensorHeightMm / 2;
    const Vec2d raster = rasterOfUprightSensorPointMm(film, {rx, ry});
    SplitMix64 rng(9);
    double s = 0, s2 = 0;
    const int n = 40000;
    for (int i = 0; i < n; ++i) {
      CameraSample cs;
      cs.film = {float(raster.x), float(raster.y)};
      cs.lens = {float(rng.uniform()), float(rng.uniform())};
      const auto r = cam.generateRay(cs);
      const double w = r ? r->weight : 0.0;
      s += w;
      s2 += w * w;
    }
    camera.push_back(s / n);
    camSigma.push_back(std::sqrt((s2 / n - (s / n) * (s / n)) / n));
    // Brute force, in lens space (the film point is inverted: -rx, -ry).
    const Vec3d fp{-rx, -ry, filmZ};
    double b = 0, b2 = 0;
    const int m = 500000;
    for (int i = 0; i < m; ++i) {
      const Vec3d q{(2 * rng.uniform() - 1) * half, (2 * rng.uniform() - 1) * half, planeZ};
      double w = 0;
      if (lens.traceFromFilm({fp, q - fp})) {
        farthestPassing = std::max({farthestPassing, std::abs(q.x), std::abs(q.y)});
        const double dz = filmZ - planeZ, d2 = lengthSquared(q - fp);
        w = 4 * half * half * dz * dz / (d2 * d2);
      }
      b += w;
      b2 += w * w;
    }
    brute.push_back(b / m);
    bruteSigma.push_back(std::sqrt((b2 / m - (b / m) * (b / m)) / m));
  }
  EXPECT_LT(farthestPassing, 0.95 * half) << "the brute-force square must hold every passing ray";
  // Absolute E/L at every film point: the camera's weights carry the
  // normalized exposure 4 N^2 / pi, known in closed form; the brute force is
  // E/L itself. Independent estimates, so their sigmas add in quadrature.
  const double ideal = idealIrradianceRatio(cam.fNumber());
  for (std::size_t i = 0; i < camera.size(); ++i) {
    const double e = camera[i] * ideal, eSigma = camSigma[i] * ideal;
    const double sigma = std::hypot(eSigma, bruteSigma[i]);
    EXPECT_NEAR(e, brute[i], 4 * sigma) << "film point " << i;
    std::printf(
        "E/L at film point %zu: camera %.5f +- %.5f, brute force %.5f +- %.5f (relative %.4f vs %.4f)\n", i,
        e, eSigma, brute[i], bruteSigma[i], camera[i] / camera[0], brute[i] / brute[0]);
  }
  // Natural plus optical vignetting: the corner gets well under the centre.
  EXPECT_LT(camera.back() / camera[0], 0.9);
}

// With blades, the out-of-focus image of a point is the polygon: an
// on-axis point far out of focus spreads into a blur whose outline has the
// polygon's corners (farthest point at the circumradius, nearest edge at
// the inradius), and the light through it equals the round stop's.
TEST(LensCamera, BladesKeepTheExposureOfTheFNumber) {
  const LensCamera round = makeLens(5.6, kInfinity), hex = makeLens(5.6, kInfinity, {6, 0.0});
  EXPECT_NEAR(hex.fNumber(), 5.6, 1e-9);
  double a = 0, b = 0;
  SplitMix64 rng(13);
  const int n = 40000;
  for (int i = 0; i < n; ++i) {
    CameraSample cs;
    cs.film = {320.f, 180.f};
    cs.lens = {float(rng.uniform()), float(rng.uniform())};
    if (const auto r = round.generateRay(cs)) a += r->weight;
    if (const auto r = hex.generateRay(cs)) b += r->weight;
  }
  EXPECT_NEAR(b / a, 1.0, 0.02);
}

TEST(LensCamera, CannotFocusCloserThanTheLensAllows) {
  EXPECT_THROW(makeLens(4, 0.02), InputError);
}

// The renderer asks for rays in batches (generateRays, traced together):
// the same rays and weights, bit for bit, as one sample at a time, with and
// without blades.
TEST(LensCamera, BatchedRaysEqualOneAtATime) {
  for (const int blades : {0, 6}) {
    ApertureShape shape;
    shape.blades = blades;
    const LensCamera cam = makeLens(2.8, 2.0, shape);
    SplitMix64 rng(11);
    std::vector<CameraSample> samples(100);
    for (CameraSample& s : samples) {
      s.film = {float(rng.uniform() * 640), float(rng.uniform() * 360)};
      s.lens = {float(rng.uniform()), float(rng.uniform())};
    }
    std::vector<std::optional<CameraRay>> batched(samples.size());
    cam.generateRays(samples, batched);
    int passed = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const std::optional<CameraRay> one = cam.generateRay(samples[i]);
      ASSERT_EQ(one.has_value(), batched[i].has_value()) << i;
      if (!one) continue;
      ++passed;
      EXPECT_EQ(std::memcmp(&one->ray.origin, &batched[i]->ray.origin, sizeof(Vec3f)), 0) << i;
      EXPECT_EQ(std::memcmp(&one->ray.direction, &batched[i]->ray.direction, sizeof(Vec3f)), 0) << i;
      EXPECT_EQ(one->weight, batched[i]->weight) << i;
    }
    EXPECT_GT(passed, 60) << "blades " << blades;
  }
}

// Coatings scale each camera ray's weight by its Fresnel transmittance and
// leave the geometry alone; the camera says which coating it models.
TEST(LensCamera, CoatingsWeightRaysByTheirTransmittance) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = 2.8;
  p.focusMetres = 2.0;
  const LensCamera lossless(Transform(), test::testFilm(), test::lectureDoubleGauss(0.5), p, Exposure{},
                            warnings);
  p.coatings = Coating::None;
  const LensCamera uncoated(Transform(), test::testFilm(), test::lectureDoubleGauss(0.5), p, Exposure{},
                            warnings);
  EXPECT_EQ(lossless.info().coatings, "");
  EXPECT_EQ(uncoated.info().coatings, "none");
  EXPECT_NE(uncoated.describe().find("coatings=none"), std::string::npos);
  SplitMix64 rng(5);
  int passed = 0;
  for (int i = 0; i < 200; ++i) {
    CameraSample s;
    s.film = {float(rng.uniform() * 640), float(rng.uniform() * 360)};
    s.lens = {float(rng.uniform()), float(rng.uniform())};
    const auto a = lossless.generateRay(s), b = uncoated.generateRay(s);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (!a) continue;
    ++passed;
    EXPECT_EQ(std::memcmp(&a->ray.direction, &b->ray.direction, sizeof(Vec3f)), 0);
    // Ten uncoated glass-air surfaces of n ~ 1.6-1.7 (about 6% each) and two
    // cemented ones: roughly 0.94^8 of the light gets through.
    const double ratio = b->weight / a->weight;
    EXPECT_GT(ratio, 0.55);
    EXPECT_LT(ratio, 0.7);
  }
  EXPECT_GT(passed, 100);
}

}  // namespace
}  // namespace lensrt
