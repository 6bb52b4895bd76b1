// Spot diagrams against geometric closed forms.
#include "optics/spot_diagram.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/warnings.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

LensPrescription dgauss() {
  return loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-50mm.dat");
}

TEST(SpotDiagram, DefocusBlursIntoAUniformDiscOfRadiusDeltaOverTwoN) {
  Warnings warnings;
  const LensSystem lens(stopDown(dgauss(), 16.0, warnings));
  const double film = focusFilmDistance(lens, kInfinity);
  const double delta = 1.0;
  const SpotDiagram spot = spotDiagram(lens, {0.0, kInfinity}, film + delta, 41);
  ASSERT_GT(spot.points.size(), 1000u);
  const double radius = delta / (2.0 * lens.paraxial().fNumber);
  // A uniform disc of radius R has RMS radius R / sqrt(2).
  EXPECT_NEAR(spot.rmsRadiusMm, radius / std::sqrt(2.0), 0.03 * radius);
  EXPECT_NEAR(spot.maxRadiusMm, radius, 0.05 * radius);
  EXPECT_NEAR(spot.centroid.x, 0.0, 1e-9);
}

TEST(SpotDiagram, InFocusOnAxisIsMicronsAndGrowsOffAxis) {
  Warnings warnings;
  const LensSystem lens(stopDown(dgauss(), 8.0, warnings));
  const double film = focusFilmDistance(lens, kInfinity);
  const SpotDiagram axis = spotDiagram(lens, {0.0, kInfinity}, film, 31);
  // Well corrected at f/8: geometric blur inside the Airy radius 1.22 lambda N.
  EXPECT_LT(axis.rmsRadiusMm, 1.22 * 587.6e-6 * 8.0);
  const SpotDiagram edge = spotDiagram(lens, {20.0, kInfinity}, film, 31);
  ASSERT_FALSE(edge.points.empty());
  EXPECT_GT(edge.rmsRadiusMm, 2.0 * axis.rmsRadiusMm);
  // The image is inverted: a field toward +x lands at -x, near f tan(theta).
  EXPECT_NEAR(edge.centroid.x, -lens.paraxial().efl * std::tan(20.0 * kPi / 180.0), 0.05 * 18.3);
}

}  // namespace
}  // namespace lensrt
