// LensSystem::traceFromSceneWithFlare, the light's way through the lens
// (particle tracing): rays from a point at infinity cross the front element's
// clear aperture and reflect or refract at every surface. Checked here:
// - energy: per ray, what reaches the film, what leaves the front again,
//   what the stop and the barrel absorb and what the reflection limit drops
//   add up to what entered; with many reflections allowed the first three
//   alone do, within 1%; the film gets at least what it gets without flare;
//   a plate against its incoherent sums;
// - geometry: every ghost's centroid on the film lies on the line through
//   the centre and the direct image (rotational symmetry), on axis at the
//   centre, within 1 px of 10 um;
// - strength: the brightest ghost over the direct image equals R_i R_j (at
//   normal incidence, from the indices) times the part of the ghost bundle
//   the apertures pass over the direct one's (counted with the deterministic
//   traceGhostFromScene on a grid of entrance rays), within 20%.
// Injected bugs and what they gave are noted at each test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "core/warnings.h"
#include "optics/focus.h"
#include "optics/lens_system.h"
#include "optics_test_util.h"
#include "split_mix_for_tests.h"

namespace lensrt {
namespace {

using End = LensSystem::FlareTrace::End;

using test::SplitMix;

// A ray from a point at infinity in `direction` (toward +z) through the
// point (x, y) of the front vertex plane, started 20 mm before it.
LensRay entering(const Vec3d& direction, double x, double y) {
  const Vec3d d = normalize(direction);
  return {Vec3d{x, y, 0.0} - d * (20.0 / d.z), d};
}

// A point uniform over the disc of radius r.
std::pair<double, double> discPoint(SplitMix& random, double r) {
  const double rho = r * std::sqrt(random()), phi = 2 * kPi * random();
  return {rho * std::cos(phi), rho * std::sin(phi)};
}

LensSystem stopped(const char* name, double fNumber, std::optional<Coating> coating) {
  Warnings warnings;
  return LensSystem(stopDown(test::libraryLens(name), fNumber, warnings), coating);
}

// Where the flux goes, summed over rays of weight 1.
struct Balance {
  double entering = 0, film = 0, front = 0, absorbed = 0, truncated = 0;
  double ghosts = 0;  // the part of `film` after reflections
};

Balance balance(const LensSystem& lens, const LensSystem::FlareOptions& options, const Vec3d& direction,
                int rays, std::uint64_t seed) {
  SplitMix random{seed};
  Balance b;
  const double radius = lens.frontApertureRadius();
  for (int k = 0; k < rays; ++k) {
    const auto [x, y] = discPoint(random, radius);
    const auto t = lens.traceFromSceneWithFlare(entering(direction, x, y), options, random);
    b.entering += 1;
    if (t.end == End::Film) b.film += t.ray.transmittance;
    if (t.end == End::Film && t.reflections > 0) b.ghosts += t.ray.transmittance;
    if (t.end == End::Scene) b.front += t.ray.transmittance;
    b.absorbed += t.absorbed;
    b.truncated += t.truncated;
  }
  return b;
}

// Light is moved, never created. Measured (dgauss-50mm f/2.8 uncoated, 8.6
// degrees off axis, of the flux entering the front): film 0.3233, out of
// the front 0.2127, absorbed 0.4535, dropped by the 2-reflection limit 0.010;
// with 64 reflections 0.3230 + 0.2192 + 0.4578 (nothing dropped); flare off
// 0.3043, flare on 0.3220 (its direct part 0.3029). Injected: a forced
// refraction that keeps its weight (no 1 - R at the limit) makes the four
// add up to 1.0095 of what entered; reflecting with probability R and also
// weighting by R, to 0.70.
TEST(FlareLight, LightIsMovedNeverCreated) {
  const LensSystem lens = stopped("dgauss-50mm", 2.8, Coating::None);
  const Vec3d direction{std::sin(0.15), 0.0, std::cos(0.15)};
  const int rays = 200000;
  for (const double barrel : {0.0, 0.5}) {
    for (const int reflections : {2, 64}) {
      SCOPED_TRACE(testing::Message() << "barrel " << barrel << ", reflections " << reflections);
      const Balance b = balance(lens, {reflections, barrel, {}}, direction, rays, 11);
      // Every ray's weight ends in one of the four: exact up to rounding.
      EXPECT_NEAR(b.film + b.front + b.absorbed + b.truncated, b.entering, 1e-9 * b.entering);
      if (reflections == 64) {
        EXPECT_LT(b.truncated, 1e-4 * b.entering);
        EXPECT_NEAR(b.film + b.front + b.absorbed, b.entering, 0.01 * b.entering);
      }
      std::printf(
          "barrel %.1f, %d reflections: film %.5f front %.5f absorbed %.5f truncated %.2g (ghosts %.5f)\n",
          barrel, reflections, b.film / b.entering, b.front / b.entering, b.absorbed / b.entering,
          b.truncated / b.entering, b.ghosts / b.entering);
    }
  }
  // Flare off: rays over the same aperture refracted at every surface with
  // the Fresnel transmittance (traceFromScene of the uncoated lens), other
  // samples than flare on's. Flare only adds.
  SplitMix random{11};
  double off = 0;
  const double radius = lens.frontApertureRadius();
  for (int k = 0; k < rays; ++k) {
    const auto [x, y] = discPoint(random, radius);
    if (const auto r = lens.traceFromScene(entering(direction, x, y))) off += r->transmittance;
  }
  const Balance on = balance(lens, {2, 0.0, {}}, direction, rays, 23);
  std::printf("flare off %.5f, on %.5f\n", off / rays, on.film / on.entering);
  // The direct part agrees with flare off within its noise (a Bernoulli
  // mean of about 0.35 over 200 000 rays: 4 standard errors, 0.0043), and
  // the ghosts come on top.
  EXPECT_NEAR((on.film - on.ghosts) / on.entering, off / rays, 0.0043);
  EXPECT_GT(on.ghosts, 0.0);
  EXPECT_GT(on.film / on.entering, off / rays);
}

// A plate at normal incidence: the light crossing it with every number of
// inner reflections is (1 - R) / (1 + R), the light reflected back out of the
// front 2 R / (1 + R), nothing absorbed.
TEST(FlareLight, APlateSplitsTheLightAsItsIncoherentSums) {
  const double n = 3.5, r = std::pow((n - 1) / (n + 1), 2);
  LensPrescription plate;
  plate.name = "plate";
  Surface front, back, stop;
  front.radius = 1e7, front.thickness = 5, front.apertureDiameter = 10, front.medium.nd = n;
  back.radius = -1e7, back.thickness = 1, back.apertureDiameter = 10;
  stop.isStop = true, stop.apertureDiameter = 10, stop.thickness = 10;
  plate.surfaces = {front, back, stop};
  const LensSystem lens(plate, Coating::None);
  const int rays = 200000;
  SplitMix random{5};
  double film = 0, front_ = 0, absorbed = 0;
  for (int k = 0; k < rays; ++k) {
    const auto t = lens.traceFromSceneWithFlare({{0, 0, -10}, {0, 0, 1}}, {64, 0.0, {}}, random);
    (t.end == End::Film ? film : t.end == End::Scene ? front_ : absorbed) += t.ray.transmittance;
  }
  const double transmitted = (1 - r) / (1 + r);
  const double tolerance = 4 * std::sqrt(transmitted * (1 - transmitted) / rays);  // 0.0043
  EXPECT_NEAR(film / rays, transmitted, tolerance);
  EXPECT_NEAR(front_ / rays, 1 - transmitted, tolerance);
  EXPECT_EQ(absorbed, 0.0);
}

// The barrel: a ray outside the front element's clear aperture meets its
// mount and comes back toward the scene with probability K, its directions
// Lambertian about the axis (the mean cosine 2/3, the mean squared cosine
// 1/2). Measured with K = 0.3 over 200 000 rays: 0.3002 back, mean cosine
// 0.6663, mean squared 0.4993. Injected: directions uniform over the
// hemisphere give 0.4993 and 0.3322.
TEST(FlareLight, TheBarrelScattersItsReflectanceDiffusely) {
  LensPrescription flat;
  flat.name = "window";
  Surface front, back, stop;
  front.radius = 1e7, front.thickness = 5, front.apertureDiameter = 10, front.medium.nd = 1.5;
  back.radius = -1e7, back.thickness = 1, back.apertureDiameter = 10;
  stop.isStop = true, stop.apertureDiameter = 10, stop.thickness = 10;
  flat.surfaces = {front, back, stop};
  const LensSystem lens(flat, Coating::None);
  const double k = 0.3;
  const int rays = 200000;
  SplitMix random{31};
  double back_ = 0, cosine = 0, cosine2 = 0;
  for (int i = 0; i < rays; ++i) {
    // Entering 6 to 7 mm off axis: outside the 5 mm clear aperture.
    const double r = 6 + random(), phi = 2 * kPi * random();
    const auto t = lens.traceFromSceneWithFlare({{r * std::cos(phi), r * std::sin(phi), -10}, {0, 0, 1}},
                                                {2, k, {}}, random);
    if (t.end != End::Scene) continue;
    EXPECT_TRUE(t.reflections == 1 && t.bounces[0].barrel && t.bounces[0].surface == 0);
    back_ += t.ray.transmittance;
    cosine += -t.ray.direction.z;
    cosine2 += t.ray.direction.z * t.ray.direction.z;
  }
  std::printf("barrel: %.4f back, mean cosine %.4f, mean squared %.4f\n", back_ / rays, cosine / back_,
              cosine2 / back_);
  EXPECT_NEAR(back_ / rays, k, 4 * std::sqrt(k * (1 - k) / rays));
  const double n = back_;  // about 60 000 rays; the cosine's variance is E[c^2] - E[c]^2 = 1/18
  EXPECT_NEAR(cosine / n, 2.0 / 3.0, 4 * std::sqrt(1.0 / 18 / n));
  EXPECT_NEAR(cosine2 / n, 0.5, 4 * std::sqrt(1.0 / 12 / n));  // E[c^4] - E[c^2]^2 = 1/3 - 1/4
}

// The film of a lens focused at infinity, and a histogram of what lands on
// it per path: the direct image (no reflection) and each two-reflection
// ghost (first, second), by the surfaces the trace records.
struct Spot {
  double w = 0, x = 0, y = 0;
  int count = 0;
  void add(double weight, double px, double py) {
    w += weight, x += weight * px, y += weight * py;
    ++count;
  }
  double cx() const { return x / w; }
  double cy() const { return y / w; }
};
using Histogram = std::map<std::pair<int, int>, Spot>;  // (-1, -1): the direct image

// Paired: each entrance point is traced again mirrored across the plane
// through the axis and the light (on axis: turned by 180 degrees), with the
// same random numbers. The pair is as good a sample of the flux as two
// independent points, and where the trace keeps the lens's symmetry the two
// land mirrored, so the noise across the line cancels and what is left of
// a centroid's distance from it is the trace's own asymmetry.
Histogram filmHistogram(const LensSystem& lens, const Vec3d& direction, int rays, std::uint64_t seed,
                        bool paired) {
  const double filmZ = lens.rearZ() + focusFilmDistance(lens, kInfinity);
  SplitMix random{seed};
  Histogram h;
  const double radius = lens.frontApertureRadius();
  const auto trace = [&](double x, double y, SplitMix& r) {
    const auto t = lens.traceFromSceneWithFlare(entering(direction, x, y), {2, 0.0, {}}, r);
    if (t.end != End::Film || (t.reflections != 0 && t.reflections != 2)) return;
    const LensRay& ray = t.ray;
    const double s = (filmZ - ray.origin.z) / ray.direction.z;
    const std::pair key =
        t.reflections == 0 ? std::pair{-1, -1} : std::pair{t.bounces[0].surface, t.bounces[1].surface};
    h[key].add(ray.transmittance, ray.origin.x + s * ray.direction.x, ray.origin.y + s * ray.direction.y);
  };
  // The mirror: across the plane of the axis and (ux, uy), or the point turned by 180 degrees.
  const double len = std::hypot(direction.x, direction.y);
  const double ux = len > 0 ? direction.x / len : 0, uy = len > 0 ? direction.y / len : 0;
  for (int k = 0; k < (paired ? rays / 2 : rays); ++k) {
    const auto [x, y] = discPoint(random, radius);
    SplitMix again = random;
    trace(x, y, random);
    if (!paired) continue;
    const double along = x * ux + y * uy;
    if (len > 0)
      trace(2 * along * ux - x, 2 * along * uy - y, again);
    else
      trace(-x, -y, again);
  }
  return h;
}

constexpr double kPixelMm = 0.010;  // the stated pixel pitch

// The largest distance of a ghost's centroid from the line through the
// centre along (ux, uy), in pixels, over the ghosts of at least 100 rays.
struct LineCheck {
  int ghosts = 0;
  double worstPx = 0;
};
LineCheck offTheLine(const Histogram& h, double ux, double uy) {
  LineCheck c;
  for (const auto& [pair, spot] : h) {
    if (pair.first < 0 || spot.count < 100) continue;
    c.worstPx = std::max(c.worstPx, std::abs(-uy * spot.cx() + ux * spot.cy()) / kPixelMm);
    ++c.ghosts;
  }
  return c;
}

// A point light 10 degrees off axis at an azimuth of 30 degrees (the
// direct image 8.8 mm off centre), 2 000 000 rays in mirrored pairs: 27
// ghosts of at least 100 rays, the worst 1e-11 px off the line. Without the
// pairing the centroids' standard errors across the line reach 40 px (the
// ghosts are millimetres wide), too noisy for a 1 px test. Injected: the
// normals at reflections and refractions taken 10 um off the surface's
// axis (a decentred surface) puts ghosts 6.4 px off the line, and on axis
// 5.7 px off centre.
TEST(FlareLight, GhostsLieOnTheLineThroughTheCentreAndTheImage) {
  const LensSystem lens = stopped("dgauss-50mm", 4.0, Coating::None);
  const double field = 10 * kPi / 180, azimuth = 30 * kPi / 180;
  const Vec3d direction{std::sin(field) * std::cos(azimuth), std::sin(field) * std::sin(azimuth),
                        std::cos(field)};
  const Histogram h = filmHistogram(lens, direction, 2000000, 17, true);
  const Spot& direct = h.at({-1, -1});
  const double len = std::hypot(direct.cx(), direct.cy());
  ASSERT_GT(len, 5.0);
  // The image lies along the light's azimuth (lens space: where the light heads).
  EXPECT_NEAR(std::atan2(direct.cy(), direct.cx()), azimuth, 1e-9);
  // The line through the centre and the image, along the image's centroid.
  const LineCheck c = offTheLine(h, direct.cx() / len, direct.cy() / len);
  std::printf("%d ghosts, the worst %.3g px off the line\n", c.ghosts, c.worstPx);
  EXPECT_GE(c.ghosts, 20);
  EXPECT_LT(c.worstPx, 1.0);
}

TEST(FlareLight, OnAxisEveryGhostIsCentred) {
  const LensSystem lens = stopped("dgauss-50mm", 4.0, Coating::None);
  const Histogram h = filmHistogram(lens, {0, 0, 1}, 2000000, 19, true);
  const LineCheck offY = offTheLine(h, 1, 0), offX = offTheLine(h, 0, 1);
  std::printf("on axis: %d ghosts, the worst %.3g px off centre in x, %.3g in y\n", offX.ghosts, offX.worstPx,
              offY.worstPx);
  EXPECT_GE(offX.ghosts, 20);
  EXPECT_LT(offX.worstPx, 1.0);
  EXPECT_LT(offY.worstPx, 1.0);
}

// The brightest ghost's flux over the direct image's, against the estimate
// from its surface pair. An axial bundle through dgauss-50mm f/2.8 uncoated,
// 2 000 000 rays: ghost 10,9 (3259 rays), 0.004963 of the direct image for
// an estimate of 0.00485 (R = 0.0696 twice, all of the ghost's bundle passes
// where the direct one does): 1.023. The surfaces between the pair, which the
// ghost crosses twice more than the direct image, would take their (1 - R)^2
// each, which the estimate leaves out: none here. Injected: weighting a
// reflection by R as well as choosing it with probability R gives 0.0051 of
// the estimate; a forced refraction that keeps its weight, 1.42 (ghost 2,0).
TEST(FlareLight, TheBrightestGhostHasItsSurfacePairsStrength) {
  const LensSystem lens = stopped("dgauss-50mm", 2.8, Coating::None);
  const Histogram h = filmHistogram(lens, {0, 0, 1}, 2000000, 29, false);
  const Spot& direct = h.at({-1, -1});
  std::pair<int, int> brightest{-1, -1};
  double brightestFlux = 0;
  for (const auto& [pair, spot] : h)
    if (pair.first >= 0 && spot.w > brightestFlux) brightest = pair, brightestFlux = spot.w;
  ASSERT_GE(brightest.first, 0);
  const double measured = brightestFlux / direct.w;
  // R at normal incidence from the indices on either side.
  const LensPrescription& p = lens.prescription();
  const auto index = [&](int i) { return i < 0 ? 1.0 : p.surfaces[std::size_t(i)].medium.nd; };
  const auto reflectance = [&](int i) {
    return std::pow((index(i) - index(i - 1)) / (index(i) + index(i - 1)), 2);
  };
  // The part passing: a 401x401 grid over the front aperture, counted.
  const LensSystem lossless(p);
  const int n = 401;
  const double radius = lens.frontApertureRadius();
  int ghostPassing = 0, directPassing = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const double x = radius * (2.0 * (a + 0.5) / n - 1), y = radius * (2.0 * (b + 0.5) / n - 1);
      if (x * x + y * y > radius * radius) continue;
      const LensRay in = entering({0, 0, 1}, x, y);
      directPassing += lossless.traceFromScene(in).has_value();
      ghostPassing += lossless.traceGhostFromScene(in, brightest.first, brightest.second).has_value();
    }
  const double estimate =
      reflectance(brightest.first) * reflectance(brightest.second) * ghostPassing / directPassing;
  std::printf(
      "brightest ghost %d,%d (%d rays): %.4g of the direct image, estimate %.4g (R %.4f x %.4f, passing "
      "%.4f)\n",
      brightest.first, brightest.second, h.at(brightest).count, measured, estimate,
      reflectance(brightest.first), reflectance(brightest.second), double(ghostPassing) / directPassing);
  EXPECT_NEAR(measured / estimate, 1.0, 0.2);
}

// Each path's end and the pairs of surfaces it reflected at, over many rays:
// the flux per ending (sum and sum of squares, for the standard error).
struct Ledger {
  struct Sum {
    double w = 0, w2 = 0;
    int paths = 0;
    void add(double x) { w += x, w2 += x * x, ++paths; }
    // The standard error of the mean over `rays` rays (the others add 0).
    double error(int rays) const {
      return std::sqrt(std::max(0.0, w2 / rays - (w / rays) * (w / rays)) / rays);
    }
  };
  Sum direct, front;
  std::map<std::pair<int, int>, Sum> ghosts;  // on the film, by (first, second) reflecting surface
};
Ledger ledger(const LensSystem& lens, const LensSystem::FlareOptions& options, int rays, std::uint64_t seed) {
  SplitMix random{seed};
  Ledger l;
  const Vec3d direction{std::sin(0.15), 0.0, std::cos(0.15)};
  for (int k = 0; k < rays; ++k) {
    const auto [x, y] = discPoint(random, lens.frontApertureRadius());
    const auto t = lens.traceFromSceneWithFlare(entering(direction, x, y), options, random);
    if (t.end == End::Scene) l.front.add(t.ray.transmittance);
    if (t.end != End::Film) continue;
    if (t.reflections == 0) l.direct.add(t.ray.transmittance);
    if (t.reflections == 2) l.ghosts[{t.bounces[0].surface, t.bounces[1].surface}].add(t.ray.transmittance);
  }
  return l;
}

// The light pass's reflection boost (FlareOptions::reflectionBoost): paths
// reflect with probability min(0.5, 4 R) and carry R / q or (1 - R) / (1 - q),
// so that more of them make ghosts, and each ghost, the direct image and the
// light sent back out of the front keep their expected flux. dgauss-50mm at
// f/2.8 uncoated, 8.6 degrees off axis, 200 000 rays each. Measured: 4.3
// times the two-reflection paths on the film (22 067 against 5 149), the
// ghosts' standard errors 1.6 to 3 times smaller; the direct image 0.3013
// +- 0.0030 against 0.3043 +- 0.0010 (its paths fewer), the five strongest
// ghosts within 1.6 standard errors. Injected: dropping the (1 - R) / (1 -
// q) of a refraction puts the direct image at 0.048 and every ghost at 1/2
// to 1/6 of its flux; dropping the R / q of a reflection, the ghosts at 15
// times theirs.
TEST(FlareLight, AReflectionBoostKeepsEveryGhostsFlux) {
  const LensSystem lens = stopped("dgauss-50mm", 2.8, Coating::None);
  const int rays = 200000;
  const Ledger plain = ledger(lens, {2, 0.0, {}, 1.0}, rays, 11);
  const Ledger boosted = ledger(lens, {2, 0.0, {}, 4.0}, rays, 13);
  const auto agree = [&](const Ledger::Sum& a, const Ledger::Sum& b, const char* what) {
    const double sigma = std::hypot(a.error(rays), b.error(rays));
    std::printf("%s: %.6f +- %.6f boosted, %.6f +- %.6f plain (%d and %d paths)\n", what, b.w / rays,
                b.error(rays), a.w / rays, a.error(rays), b.paths, a.paths);
    EXPECT_NEAR(b.w / rays, a.w / rays, 4 * sigma) << what;
  };
  agree(plain.direct, boosted.direct, "direct image");
  agree(plain.front, boosted.front, "out of the front");
  std::vector<std::pair<double, std::pair<int, int>>> strongest;
  int plainGhostPaths = 0, boostedGhostPaths = 0;
  for (const auto& [pair, sum] : plain.ghosts)
    strongest.push_back({sum.w, pair}), plainGhostPaths += sum.paths;
  for (const auto& [pair, sum] : boosted.ghosts) boostedGhostPaths += sum.paths;
  std::sort(strongest.rbegin(), strongest.rend());
  ASSERT_GE(strongest.size(), 5u);
  for (std::size_t g = 0; g < 5; ++g) {
    const std::pair<int, int> pair = strongest[g].second;
    const std::string what = "ghost " + std::to_string(pair.first) + "," + std::to_string(pair.second);
    const auto found = boosted.ghosts.find(pair);
    agree(plain.ghosts.at(pair), found == boosted.ghosts.end() ? Ledger::Sum{} : found->second, what.c_str());
  }
  std::printf("two-reflection paths on the film: %d boosted, %d plain\n", boostedGhostPaths, plainGhostPaths);
  EXPECT_GT(boostedGhostPaths, 2 * plainGhostPaths);
}

// A ghost made on purpose (FlareOptions::ghost): each path reflects at the
// pair's two surfaces and refracts at every other, weighted R there and 1 - R
// elsewhere, so the mean over paths is that ghost's flux in the
// reflect-or-refract trace. The five strongest ghosts of dgauss-50mm at f/2.8
// uncoated, 8.6 degrees off axis, 100 000 paths each against the 200 000
// plain ones, about half of them reaching the film. Measured: within 1
// standard error each, the made ghost's own error 13 to 22 times smaller;
// ghost 10,9: 0.001485 against 0.001564 +- 0.000085. Injected: the forced
// reflections weighted 1 (as if each had been picked with probability R)
// give 190 to 240 times.
TEST(FlareLight, AGhostMadeOnPurposeCarriesItsExpectedFlux) {
  const LensSystem lens = stopped("dgauss-50mm", 2.8, Coating::None);
  const int plainRays = 200000, rays = 100000;
  const Ledger plain = ledger(lens, {2, 0.0, {}, 1.0}, plainRays, 11);
  std::vector<std::pair<double, std::pair<int, int>>> strongest;
  for (const auto& [pair, sum] : plain.ghosts) strongest.push_back({sum.w, pair});
  std::sort(strongest.rbegin(), strongest.rend());
  ASSERT_GE(strongest.size(), 5u);
  const Vec3d direction{std::sin(0.15), 0.0, std::cos(0.15)};
  for (std::size_t g = 0; g < 5; ++g) {
    const std::pair<int, int> pair = strongest[g].second;
    LensSystem::FlareOptions options{2, 0.0, {}, 1.0, pair};
    SplitMix random{100 + g};
    Ledger::Sum made;
    for (int k = 0; k < rays; ++k) {
      const auto [x, y] = discPoint(random, lens.frontApertureRadius());
      const auto t = lens.traceFromSceneWithFlare(entering(direction, x, y), options, random);
      if (t.end != End::Film) continue;
      ASSERT_EQ(t.reflections, 2);
      EXPECT_EQ(t.bounces[0].surface, pair.first);
      EXPECT_EQ(t.bounces[1].surface, pair.second);
      made.add(t.ray.transmittance);
    }
    const Ledger::Sum& reference = plain.ghosts.at(pair);
    const double sigma = std::hypot(made.error(rays), reference.error(plainRays));
    std::printf("ghost %d,%d made: %.6f +- %.6f (%d of %d paths on the film), by choice %.6f +- %.6f\n",
                pair.first, pair.second, made.w / rays, made.error(rays), made.paths, rays,
                reference.w / plainRays, reference.error(plainRays));
    EXPECT_NEAR(made.w / rays, reference.w / plainRays, 4 * sigma);
  }
  // Only from the scene, and not with the barrel (whose scatters are reflections too).
  LensSystem::FlareOptions barrel{2, 0.5, {}, 1.0, std::pair{10, 9}};
  SplitMix random{1};
  EXPECT_THROW(lens.traceFromSceneWithFlare(entering(direction, 0, 0), barrel, random),
               std::invalid_argument);
}

}  // namespace
}  // namespace lensrt
