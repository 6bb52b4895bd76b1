// Exposure: normalized records L on axis at every f-number; physical obeys
// reciprocity (equal N^2 / t, equal value) and ISO 12232's saturation point.
#include <gtest/gtest.h>

#include <cmath>

#include "camera/lens_camera.h"
#include "camera/pinhole_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

double centreWeight(const Camera& cam, int samples = 1) {
  SplitMix64 rng(21);
  double sum = 0;
  for (int i = 0; i < samples; ++i) {
    CameraSample s;
    s.film = {320.f, 180.f};
    s.lens = {float(rng.uniform()), float(rng.uniform())};
    if (const auto r = cam.generateRay(s)) sum += r->weight;
  }
  return sum / samples;
}

ThinLensCamera thin(double n, const Exposure& e) {
  ThinLensParams p;
  p.focalLengthMm = 50;
  p.fNumber = n;
  p.focusMetres = kInfinity;
  return ThinLensCamera(Transform(), test::testFilm(), p, e);
}

Exposure physical(double shutter, double iso) {
  return {ExposureMode::Physical, shutter, iso};
}

TEST(Exposure, NormalizedRecordsRadianceOnAxisAtEveryFNumber) {
  for (const double n : {1.0, 2.8, 16.0}) EXPECT_NEAR(centreWeight(thin(n, {})), 1.0, 1e-6);
  const PinholeCamera pin(Transform(), test::testFilm(), 0.6, Exposure{}, 8.0);
  EXPECT_NEAR(centreWeight(pin), 1.0, 1e-6);
}

TEST(Exposure, PhysicalFollowsReciprocityAndIso12232) {
  // H_v = 683 E t lux s with E = pi L / (4 N^2); value 1 at H_sat = 78 / ISO.
  const double n = 4, t = 0.02, iso = 200;
  const double expected = 683.0 * kPi / (4 * n * n) * t * iso / 78.0;
  EXPECT_NEAR(centreWeight(thin(n, physical(t, iso))), expected, 1e-6 * expected);
  // f/2.8 at 1/100 s and f/4 at 1/50 s: the same exposure up to the rounding
  // of the f-number series (2.8 for 2 sqrt 2).
  const double a = centreWeight(thin(2.8, physical(0.01, 100)));
  const double b = centreWeight(thin(4.0, physical(0.02, 100)));
  EXPECT_NEAR(a / b, (4.0 * 4.0 / 0.02) / (2.8 * 2.8 / 0.01), 1e-6);
  EXPECT_NEAR(a / b, 1.0, 0.025);
  const double exactA = centreWeight(thin(2 * std::sqrt(2.0), physical(0.01, 100)));
  EXPECT_NEAR(exactA / b, 1.0, 1e-6);
  // ISO scales the value linearly.
  EXPECT_NEAR(centreWeight(thin(4.0, physical(0.02, 400))) / b, 4.0, 1e-6);
}

// The full lens too: it collects light through its real pupil, so the
// reciprocity holds to within how well the stop's paraxial image predicts
// the passing bundle.
TEST(Exposure, FullLensReciprocityAndNormalizedLevel) {
  Warnings warnings;
  const auto lens = [&](double n, const Exposure& e) {
    LensCameraParams p;
    p.fNumber = n;
    return LensCamera(Transform(), test::testFilm(), test::lectureDoubleGauss(0.5), p, e, warnings);
  };
  const double a = centreWeight(lens(2.8, physical(1.0 / 100, 100)), 20000);
  const double b = centreWeight(lens(2.8 * std::sqrt(2.0), physical(1.0 / 50, 100)), 20000);
  EXPECT_NEAR(a / b, 1.0, 0.02);
  // Normalized: an aplanatic lens would record exactly L on axis.
  const double level = centreWeight(lens(4, {}), 20000);
  RecordProperty("full_lens_normalized_axis_level", std::to_string(level));
  EXPECT_NEAR(level, 1.0, 0.03);
}

}  // namespace
}  // namespace lensrt
