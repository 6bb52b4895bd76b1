// Exit pupil bounds: conservative (every passing ray inside), tight
// (>= 90% of sampled rays pass for dgauss-50mm at f/2 on 36x24 mm) and
// sampled with the pdf they report.
#include "optics/exit_pupil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include "core/constants.h"
#include "core/warnings.h"
#include "optics/focus.h"
#include "optics/sample_sequence.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

constexpr double kHalfDiagonal = 21.633;  // 36x24 mm

LensSystem stopped(const char* name, double fNumber) {
  Warnings warnings;  // f/2 on a f/2.03 design clamps with a warning: fine here
  return LensSystem(stopDown(test::libraryLens(name), fNumber, warnings));
}

// Random rays from film points over the frame toward a square much larger
// than the rear element; every ray that passes must lie inside the bounds.
long countEscapes(const LensSystem& lens, const ExitPupilBounds& bounds, long rays, long& passed) {
  SplitMix64 rng(5);
  const double r = 1.6 * lens.rearApertureRadius() + 5.0;
  long escapes = 0;
  passed = 0;
  for (long i = 0; i < rays; ++i) {
    const Vec2d film{(rng.uniform() - 0.5) * 36, (rng.uniform() - 0.5) * 24};
    const Vec2d pupil{(rng.uniform() - 0.5) * 2 * r, (rng.uniform() - 0.5) * 2 * r};
    const Vec3d o{film.x, film.y, bounds.filmZ()};
    if (!lens.traceFromFilm({o, Vec3d{pupil.x, pupil.y, bounds.planeZ()} - o})) continue;
    ++passed;
    escapes += bounds.pdf(film, pupil) <= 0.0;
  }
  return escapes;
}

TEST(ExitPupil, ContainsEveryPassingRayOfAMillion) {
  const LensSystem lens = stopped("dgauss-50mm", 2.0);
  const ExitPupilBounds bounds(lens, lens.rearZ() + focusFilmDistance(lens, kInfinity), kHalfDiagonal);
  long passed = 0;
  EXPECT_EQ(countEscapes(lens, bounds, 1'000'000, passed), 0);
  EXPECT_GT(passed, 50'000);
}

TEST(ExitPupil, ContainsPassingRaysForOtherLensesAndSettings) {
  struct Case {
    const char* lens;
    double fNumber, focusMm;
  };
  for (const Case c : {Case{"dgauss-50mm", 8.0, 1000.0}, Case{"wide-22mm", 0.1, kInfinity},
                       Case{"fisheye-10mm", 0.1, kInfinity}, Case{"telephoto-250mm", 0.1, 3000.0},
                       Case{"angenieux-dgauss-100mm", 0.1, kInfinity}, Case{"petzval-100mm", 4.0, 2000.0}}) {
    SCOPED_TRACE(c.lens);
    const LensSystem lens = stopped(c.lens, c.fNumber);
    const ExitPupilBounds bounds(lens, lens.rearZ() + focusFilmDistance(lens, c.focusMm), kHalfDiagonal);
    long passed = 0;
    EXPECT_EQ(countEscapes(lens, bounds, 150'000, passed), 0);
    EXPECT_GT(passed, 100);
  }
}

// A tilted film's points lie off the film plane: bounds with a depth range
// hold every passing ray from film points at any depth in it (here +-3 mm,
// a 10 deg tilt across a 36 mm frame), and still let most sampled rays pass.
// Bounds for the plane alone miss some of those rays.
TEST(ExitPupil, ContainsEveryPassingRayFromFilmPointsAcrossADepthRange) {
  const LensSystem lens = stopped("dgauss-50mm", 2.0);
  const double filmZ = lens.rearZ() + focusFilmDistance(lens, kInfinity);
  const FilmDepthRange depth{-3.0, 3.0};
  const ExitPupilBounds slab(lens, filmZ, kHalfDiagonal, 64, depth);
  const ExitPupilBounds plane(lens, filmZ, kHalfDiagonal);
  SplitMix64 rng(9);
  const double r = 1.6 * lens.rearApertureRadius() + 5.0;
  long passed = 0, escapes = 0, planeEscapes = 0, sampled = 0, sampledPassed = 0;
  for (long i = 0; i < 200'000; ++i) {
    const Vec2d film{(rng.uniform() - 0.5) * 36, (rng.uniform() - 0.5) * 24};
    const double z = filmZ + depth.min + (depth.max - depth.min) * rng.uniform();
    const Vec2d pupil{(rng.uniform() - 0.5) * 2 * r, (rng.uniform() - 0.5) * 2 * r};
    const Vec3d o{film.x, film.y, z};
    if (const auto s = slab.sample(film, {rng.uniform(), rng.uniform()})) {
      ++sampled;
      sampledPassed += lens.traceFromFilm({o, s->point - o}).has_value();
    }
    if (!lens.traceFromFilm({o, Vec3d{pupil.x, pupil.y, slab.planeZ()} - o})) continue;
    ++passed;
    escapes += slab.pdf(film, pupil) <= 0.0;
    planeEscapes += plane.pdf(film, pupil) <= 0.0;
  }
  std::printf(
      "depth range +-3 mm: %ld passing rays, %ld outside the bounds (%ld outside the plane's); "
      "%.1f%% of sampled rays pass\n",
      passed, escapes, planeEscapes, 100.0 * sampledPassed / sampled);
  EXPECT_GT(passed, 10'000);
  EXPECT_EQ(escapes, 0);
  EXPECT_GT(planeEscapes, 0) << "the depth range is needed";
  EXPECT_GE(double(sampledPassed) / sampled, 0.85);
}

TEST(ExitPupil, AtLeastNinetyPercentOfSampledRaysPass) {
  const LensSystem lens = stopped("dgauss-50mm", 2.0);
  const ExitPupilBounds bounds(lens, lens.rearZ() + focusFilmDistance(lens, kInfinity), kHalfDiagonal);
  const PupilEfficiency e = measurePupilEfficiency(lens, bounds, 36.0, 24.0, 100'000);
  EXPECT_EQ(e.empty, 0);
  EXPECT_GE(e.efficiency(), 0.90);
}

// The pdf is 1/area of the bounds, the samples land where pdf() says they
// may, and they are uniform: counts in a grid of cells match the cells'
// areas inside the bounds (measured independently by point tests).
TEST(ExitPupil, SamplesAreUniformWithTheReportedPdf) {
  const LensSystem lens = stopped("dgauss-50mm", 2.8);
  const ExitPupilBounds bounds(lens, lens.rearZ() + focusFilmDistance(lens, kInfinity), kHalfDiagonal);
  const Vec2d film{9.0, -12.0};
  SplitMix64 rng(9);
  // Cells over a square holding the bounds.
  const double half = 1.6 * lens.rearApertureRadius() + 5.0;
  constexpr int kCells = 6;
  const double cell = 2 * half / kCells;
  std::vector<double> areaInside(kCells * kCells, 0.0);
  constexpr int kProbe = 200;  // per cell side
  double totalArea = 0;
  for (int j = 0; j < kCells * kProbe; ++j)
    for (int i = 0; i < kCells * kProbe; ++i) {
      const Vec2d q{-half + (i + 0.5) * cell / kProbe, -half + (j + 0.5) * cell / kProbe};
      if (bounds.pdf(film, q) > 0) {
        const double a = (cell / kProbe) * (cell / kProbe);
        areaInside[(j / kProbe) * kCells + i / kProbe] += a;
        totalArea += a;
      }
    }
  const double pdf = 1.0 / bounds.area(std::hypot(film.x, film.y));
  EXPECT_NEAR(totalArea * pdf, 1.0, 0.01);  // the pdf integrates to one
  constexpr int kSamples = 200'000;
  std::vector<double> counts(kCells * kCells, 0.0);
  for (int k = 0; k < kSamples; ++k) {
    const auto s = bounds.sample(film, {rng.uniform(), rng.uniform()});
    ASSERT_TRUE(s);
    EXPECT_DOUBLE_EQ(s->pdf, pdf);
    const Vec2d q{s->point.x, s->point.y};
    ASSERT_GT(bounds.pdf(film, q), 0.0);
    const int i = std::clamp(static_cast<int>((q.x + half) / cell), 0, kCells - 1);
    const int j = std::clamp(static_cast<int>((q.y + half) / cell), 0, kCells - 1);
    counts[j * kCells + i] += 1;
  }
  double chi2 = 0;
  int dof = -1;
  for (int c = 0; c < kCells * kCells; ++c) {
    const double expected = kSamples * areaInside[c] / totalArea;
    if (expected < 20) continue;
    chi2 += (counts[c] - expected) * (counts[c] - expected) / expected;
    ++dof;
  }
  ASSERT_GT(dof, 3);
  // Generous: chi2 of a correct sampler is ~dof; probe discretisation adds a little.
  EXPECT_LT(chi2, 3.0 * dof + 30) << "dof " << dof;
}

// The lens camera samples a chunk of film points in one call (with AVX2 four
// lanes at a time): the same bits as sample() point by point, a pdf of 0 where
// sample() has none. Points all over the frame, beyond the image circle, on
// the axis and on the x axis; u at 0 and just below 1.
TEST(ExitPupil, BatchedSampleEqualsOneAtATime) {
  for (const char* name : {"dgauss-50mm", "wide-22mm", "fisheye-10mm"}) {
    const LensSystem lens = stopped(name, 4.0);
    const double filmZ = lens.rearZ() + focusFilmDistance(lens, 3000.0);
    const ExitPupilBounds bounds(lens, filmZ, kHalfDiagonal);
    SplitMix64 rng(17);
    std::vector<Vec2d> film, u;
    for (int i = 0; i < 20011; ++i) {  // not a multiple of the lane count
      const double reach = i % 7 == 0 ? 1.3 * kHalfDiagonal : kHalfDiagonal;
      Vec2d f{(2 * rng.uniform() - 1) * reach, (2 * rng.uniform() - 1) * reach};
      if (i % 101 == 0) f = {0, 0};
      if (i % 103 == 0) f.y = 0;
      Vec2d v{rng.uniform(), rng.uniform()};
      if (i % 11 == 0) v.x = 0;
      if (i % 13 == 0) v.x = std::nextafter(1.0, 0.0);
      film.push_back(f);
      u.push_back(v);
    }
    std::vector<PupilSample> batched(film.size());
    bounds.sample(film, u, batched);
    const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    int none = 0;
    for (std::size_t i = 0; i < film.size(); ++i) {
      const std::optional<PupilSample> one = bounds.sample(film[i], u[i]);
      if (!one) {
        ++none;
        ASSERT_EQ(batched[i].pdf, 0.0) << name << " point " << i;
        continue;
      }
      ASSERT_TRUE(same(one->pdf, batched[i].pdf) && same(one->point.x, batched[i].point.x) &&
                  same(one->point.y, batched[i].point.y) && same(one->point.z, batched[i].point.z))
          << name << " point " << i;
    }
    EXPECT_GT(none, 0) << name;  // some points lie beyond the image circle
  }
}

TEST(ExitPupil, NoBoundsBeyondTheFilmExtent) {
  const LensSystem lens = stopped("dgauss-50mm", 4.0);
  const ExitPupilBounds bounds(lens, lens.rearZ() + 40.0, 10.0);
  EXPECT_FALSE(bounds.sample({11.0, 0.0}, {0.5, 0.5}));
  EXPECT_TRUE(bounds.sample({0.0, 9.9}, {0.5, 0.5}));
}

}  // namespace
}  // namespace lensrt
