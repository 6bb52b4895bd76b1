// Ghosts take the shape of the stop: with --flare on, the camera's flare
// traces test the stop with its blade polygon (LensCamera::flareOptions), at
// every crossing. An axial point at infinity, particle-traced from the scene
// through a 6-blade stop at f/11, makes ghosts whose width across the film
// (the extent of their rays along a direction) goes from flat to flat and
// from corner to corner: the smallest over the largest is a regular
// hexagon's cos(30 deg) = 0.866, where a round stop gives 1 (the finite
// sample of the ghost's edge moves both by about 0.015). Measured, 1 000 000
// rays: ghost 10,9 (2127 rays) 0.878, round 0.984. Injected: the flare
// trace without the stop's shape gives 0.984 with 6 blades.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "camera/lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/focus.h"
#include "split_mix_for_tests.h"

namespace lensrt {
namespace {

using test::SplitMix;

LensCamera flareCamera(int blades) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = 11.0;
  p.focusMetres = kInfinity;
  p.aperture = {blades, 0.0};
  p.coatings = Coating::None;
  p.flareReflections = 2;
  return LensCamera(Transform(), test::testFilm(), test::lectureDoubleGauss(), p, Exposure{}, warnings);
}

// The film points of each two-reflection ghost of an axial point at
// infinity, by its surface pair.
std::map<std::pair<int, int>, std::vector<Vec2d>> ghosts(const LensCamera& camera, int rays) {
  const LensSystem& lens = camera.lens();
  SplitMix random{41};
  std::map<std::pair<int, int>, std::vector<Vec2d>> out;
  // Over the entrance pupil (a little wider): where the ghosts reflected
  // behind the stop come from, since they crossed it on the way in.
  const double radius = 1.1 * lens.paraxial().efl / (2 * lens.paraxial().fNumber);
  for (int k = 0; k < rays; ++k) {
    const double rho = radius * std::sqrt(random()), phi = 2 * kPi * random();
    const LensRay in{{rho * std::cos(phi), rho * std::sin(phi), -20.0}, {0, 0, 1}};
    const auto t = lens.traceFromSceneWithFlare(in, camera.flareOptions(), random);
    if (t.end != LensSystem::FlareTrace::End::Film || t.reflections != 2) continue;
    const double s = (camera.filmZ() - t.ray.origin.z) / t.ray.direction.z;
    out[{t.bounces[0].surface, t.bounces[1].surface}].push_back(
        {t.ray.origin.x + s * t.ray.direction.x, t.ray.origin.y + s * t.ray.direction.y});
  }
  return out;
}

// The smallest width over the largest, over directions every half degree.
double widthRatio(const std::vector<Vec2d>& points) {
  double least = kInfinity, most = 0;
  for (int a = 0; a < 360; ++a) {
    const double angle = a * kPi / 360, ux = std::cos(angle), uy = std::sin(angle);
    double lo = kInfinity, hi = -kInfinity;
    for (const Vec2d& p : points) {
      const double v = p.x * ux + p.y * uy;
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    least = std::min(least, hi - lo), most = std::max(most, hi - lo);
  }
  return least / most;
}

TEST(FlareStop, AGhostOfASixBladeStopIsAHexagon) {
  const double hexagon = std::cos(kPi / 6);
  for (const int blades : {6, 0}) {
    SCOPED_TRACE(testing::Message() << blades << " blades");
    const LensCamera camera = flareCamera(blades);
    ASSERT_TRUE(blades == 0 || camera.flareOptions().stop);
    const auto g = ghosts(camera, 1000000);
    // The ghost with the most rays of those reflected behind the stop: it
    // crossed the stop on the way in, the narrow beam of f/11 meets no
    // other aperture, so it is the entrance pupil's shadow, out of focus.
    const std::vector<Vec2d>* widest = nullptr;
    std::pair<int, int> which;
    for (const auto& [pair, points] : g)
      if (pair.second > camera.lens().paraxial().stopIndex && (!widest || points.size() > widest->size()))
        widest = &points, which = pair;
    ASSERT_NE(widest, nullptr);
    const double ratio = widthRatio(*widest);
    std::printf("%d blades: ghost %d,%d (%zu rays): width ratio %.4f\n", blades, which.first, which.second,
                widest->size(), ratio);
    if (blades == 6)
      EXPECT_NEAR(ratio, hexagon, 0.02);
    else
      EXPECT_GT(ratio, 0.97);
  }
}

}  // namespace
}  // namespace lensrt
