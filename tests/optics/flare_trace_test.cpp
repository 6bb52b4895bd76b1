// LensSystem::traceFromFilmWithFlare against closed forms: a glass plate of
// index n at normal incidence reflects R = ((n - 1) / (n + 1))^2 at each face,
// so light crossing it reaches the far side with (1 - R)^2 directly, and with
// every number of inner reflections (incoherent sum) (1 - R) / (1 + R); with
// at most two reflections, (1 - R)^2 (1 + R^2). The plate's faces are nearly
// flat spheres (a plate is afocal, which the lens system refuses). Keeping
// the weight of rays forced to refract after the last reflection allowed
// fails the second check (0.543 for 0.523).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "optics/lens_system.h"
#include "split_mix_for_tests.h"

namespace lensrt {
namespace {

LensPrescription plate(double n) {
  LensPrescription lens;
  lens.name = "plate";
  Surface stop;
  stop.isStop = true;
  stop.apertureDiameter = 10;
  stop.thickness = 1;
  Surface front;
  front.radius = 1e7;
  front.thickness = 5;
  front.apertureDiameter = 10;
  front.medium.nd = n;
  Surface back;
  back.radius = -1e7;
  back.thickness = 10;
  back.apertureDiameter = 10;
  lens.surfaces = {stop, front, back};
  return lens;
}

using test::SplitMix;

// The mean weight that reaches the scene, and the fractions of rays ending
// at the film and blocked, over `rays` axial rays from the film.
struct Outcome {
  double scene = 0, film = 0, blocked = 0;
};
Outcome traceAxial(const LensSystem& lens, int maxReflections, int rays) {
  SplitMix random{7};
  Outcome o;
  for (int k = 0; k < rays; ++k) {
    const auto t =
        lens.traceFromFilmWithFlare({{0, 0, lens.rearZ() + 10}, {0, 0, -1}}, maxReflections, random);
    if (t.end == LensSystem::FlareTrace::End::Scene) o.scene += t.ray.transmittance;
    if (t.end == LensSystem::FlareTrace::End::Film) o.film += 1;
    if (t.end == LensSystem::FlareTrace::End::Blocked) o.blocked += 1;
  }
  o.scene /= rays, o.film /= rays, o.blocked /= rays;
  return o;
}

TEST(FlareTrace, APlateTransmitsItsIncoherentSum) {
  // A high index (R = 0.31 a face) so that the reflected paths carry weight.
  const double n = 3.5, r = std::pow((n - 1) / (n + 1), 2), t = 1 - r;
  const LensSystem lens(plate(n), Coating::None);
  const int rays = 200000;
  // A Bernoulli mean over 200 000 rays: 4 standard errors is under 0.0045.
  const auto tolerance = [&](double p) { return 4 * std::sqrt(p * (1 - p) / rays) + 1e-9; };
  const Outcome none = traceAxial(lens, 0, rays);
  EXPECT_NEAR(none.scene, t * t, 1e-9);  // no reflections: the weight is the product, every ray
  const Outcome two = traceAxial(lens, 2, rays);
  EXPECT_NEAR(two.scene, t * t * (1 + r * r), tolerance(t * t));
  const Outcome all = traceAxial(lens, 64, rays);
  EXPECT_NEAR(all.scene, (1 - r) / (1 + r), tolerance((1 - r) / (1 + r)));
  EXPECT_NEAR(all.film, 1 - (1 - r) / (1 + r), tolerance(1 - (1 - r) / (1 + r)));
  EXPECT_EQ(all.blocked, 0.0);
}

// Every ray that leaves toward the scene did so after an even number of
// reflections, and one that returns to the film after an odd number.
TEST(FlareTrace, TheSceneSeesEvenReflectionsAndTheFilmOdd) {
  const LensSystem lens(plate(1.8), Coating::None);
  SplitMix random{3};
  for (int k = 0; k < 20000; ++k) {
    const auto t = lens.traceFromFilmWithFlare({{0.5, -0.3, lens.rearZ() + 10}, {0.01, 0.02, -1}}, 6, random);
    if (t.end == LensSystem::FlareTrace::End::Scene) {
      EXPECT_EQ(t.reflections % 2, 0);
    } else if (t.end == LensSystem::FlareTrace::End::Film) {
      EXPECT_EQ(t.reflections % 2, 1);
    }
  }
}

}  // namespace
}  // namespace lensrt
