// Exact tracing against Snell's law, reversibility and the focus condition.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/constants.h"
#include "core/error.h"
#include "core/warnings.h"
#include "optics/focus.h"
#include "optics/lens_system.h"
#include "optics/sample_sequence.h"
#include "optics_test_util.h"

namespace lensrt {
namespace {

TEST(Tracing, RefractionObeysSnellsLaw) {
  const Vec3d n{0, 0, -1};  // facing a ray travelling +z
  for (const double deg : {0.0, 10.0, 30.0, 60.0}) {
    const double a = deg * kPi / 180;
    const Vec3d d{std::sin(a), 0, std::cos(a)};
    Vec3d out;
    ASSERT_TRUE(refract(d, n, 1.0, 1.5, out));
    EXPECT_NEAR(1.0 * std::sin(a), 1.5 * out.x, 1e-12);  // n1 sin t1 = n2 sin t2
    EXPECT_NEAR(length(out), 1.0, 1e-12);
  }
  // Beyond the critical angle, glass to air reflects totally.
  const double a = std::asin(1 / 1.5) + 0.01;
  Vec3d out;
  EXPECT_FALSE(refract({std::sin(a), 0, std::cos(a)}, n, 1.5, 1.0, out));
}

TEST(Tracing, AxialRayPassesUndeviated) {
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  const auto out = lens.traceFromScene({{0, 0, -100}, {0, 0, 1}});
  ASSERT_TRUE(out);
  EXPECT_NEAR(out->origin.z, lens.rearZ(), 1e-12);
  EXPECT_NEAR(out->direction.x, 0, 1e-15);
  EXPECT_NEAR(out->direction.z, 1, 1e-15);
}

TEST(Tracing, ParallelNearAxisRaysFocusAtTheBackFocalLength) {
  const LensSystem lens(test::libraryLens("dgauss-100mm"));
  const auto out = lens.traceFromScene({{0.01, 0, -10}, {0, 0, 1}});
  ASSERT_TRUE(out);
  const double crossing = out->origin.z - out->origin.x * out->direction.z / out->direction.x;
  EXPECT_NEAR(crossing - lens.rearZ(), lens.paraxial().bfl, 1e-4);
  EXPECT_NEAR(crossing - lens.rearZ(), 72.2, 0.1);
}

// Optical paths are reversible: a ray traced from the scene, sent back from
// where it left, retraces its path out of the front of the lens.
TEST(Tracing, FilmAndSceneTracesAreInverse) {
  const LensSystem lens(test::libraryLens("dgauss-100mm"));
  SplitMix64 rng(3);
  int checked = 0;
  for (int i = 0; i < 6000; ++i) {
    const Vec3d origin{(rng.uniform() - 0.5) * 40, (rng.uniform() - 0.5) * 40, -30};
    const Vec3d target{(rng.uniform() - 0.5) * 40, (rng.uniform() - 0.5) * 40, 0};
    const LensRay in{origin, normalize(target - origin)};
    for (const double wavelength : {kWavelengthDNm, 450.0}) {
      const auto out = lens.traceFromScene(in, wavelength);
      if (!out) continue;
      const auto back = lens.traceFromFilm({out->origin, -out->direction}, wavelength);
      ASSERT_TRUE(back);
      EXPECT_NEAR(dot(back->direction, -in.direction), 1.0, 1e-12);
      // The returning ray lies on the incoming line.
      const Vec3d off = back->origin - origin;
      EXPECT_NEAR(length(off - in.direction * dot(off, in.direction)), 0.0, 1e-9);
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
}

TEST(Tracing, DispersionBendsBlueMoreThanRed) {
  // A singlet of crown glass: shorter focal length in blue (n_F > n_C), and
  // the difference is the Abbe number's definition: (n_F - n_C) = (n_d - 1)/V_d.
  LensPrescription rx = test::singlet(100.0, -100.0, 4.0, 1.5168);
  rx.surfaces[1].medium.vd = 64.17;
  const LensSystem lens(rx);
  const auto focus = [&](double wl) {
    const auto out = lens.traceFromScene({{0.01, 0, -10}, {0, 0, 1}}, wl);
    return out->origin.z - out->origin.x * out->direction.z / out->direction.x;
  };
  EXPECT_LT(focus(kWavelengthFNm), focus(kWavelengthDNm));
  EXPECT_LT(focus(kWavelengthDNm), focus(kWavelengthCNm));
  const Dispersion glass = Dispersion::of(rx.surfaces[1].medium);
  EXPECT_NEAR(glass.index(kWavelengthDNm), 1.5168, 1e-12);
  EXPECT_NEAR(glass.index(kWavelengthFNm) - glass.index(kWavelengthCNm), 0.5168 / 64.17, 1e-12);
}

// Near-axis rays from an on-axis point at the focus distance meet on the film.
TEST(Focus, RaysFromTheFocusDistanceMeetOnTheFilm) {
  for (const char* name : {"dgauss-50mm", "dgauss-100mm", "tessar-100mm", "telephoto-250mm"}) {
    SCOPED_TRACE(name);
    const LensSystem lens(test::libraryLens(name));
    const ParaxialData& p = lens.paraxial();
    for (const double distance : {700.0, 2000.0, 10000.0}) {
      const double film = focusFilmDistance(lens, distance);
      const double filmZ = lens.rearZ() + film;
      const Vec3d object{0, 0, p.entrancePupilZ - distance};
      double worst = 0;
      for (int i = 1; i <= 8; ++i) {
        const double h = 0.2 * p.entrancePupilDiameter / 2 * i / 8;  // the central fifth of the pupil
        const double phi = 0.7 * i;
        const Vec3d target{h * std::cos(phi), h * std::sin(phi), p.entrancePupilZ};
        const auto out = lens.traceFromScene({object, target - object});
        ASSERT_TRUE(out);
        const double t = (filmZ - out->origin.z) / out->direction.z;
        const Vec3d hit = out->origin + out->direction * t;
        worst = std::max(worst, std::hypot(hit.x, hit.y));
      }
      EXPECT_LT(worst, 0.004) << "at " << distance << " mm: spread " << worst * 1000 << " um";
    }
  }
}

TEST(Focus, InfinityFocusIsTheBackFocalLength) {
  const LensSystem lens(test::libraryLens("dgauss-100mm"));
  EXPECT_NEAR(focusFilmDistance(lens, kInfinity), lens.paraxial().bfl, 1e-6);
  // Closer objects need more extension (the image moves away from the lens).
  EXPECT_GT(focusFilmDistance(lens, 1000.0), focusFilmDistance(lens, 5000.0));
}

TEST(Focus, CloserThanTheLensCanFocusIsAnError) {
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  try {
    focusFilmDistance(lens, 30.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("closer than the lens can focus"), std::string::npos) << e.what();
  }
  EXPECT_THROW(focusFilmDistance(lens, -1.0), InputError);
}

TEST(StopDown, ReachesTheRequestedFNumber) {
  const LensPrescription rx = test::libraryLens("dgauss-50mm");
  Warnings warnings;
  for (const double n : {2.8, 4.0, 8.0, 16.0}) {
    const LensSystem lens(stopDown(rx, n, warnings));
    EXPECT_NEAR(lens.paraxial().fNumber, n, 1e-9);
    EXPECT_NEAR(lens.paraxial().efl, 50.358, 0.01);  // the focal length does not change
  }
  EXPECT_TRUE(warnings.all().empty());
  // Wider than the design: clamped to its widest, with a warning.
  const LensSystem wide(stopDown(rx, 1.0, warnings));
  EXPECT_NEAR(wide.paraxial().fNumber, computeParaxial(rx).fNumber, 1e-12);
  ASSERT_EQ(warnings.all().size(), 1u);
  EXPECT_NE(warnings.all().begin()->find("wider than the lens allows"), std::string::npos);
  EXPECT_THROW(stopDown(rx, 0.0, warnings), InputError);
}

// Random film->scene rays, sane or not, through every library lens at several
// f-numbers: each passes with finite unit output or is blocked; never NaN.
TEST(Tracing, NoNaNForAnyRay) {
  SplitMix64 rng(11);
  long passed = 0, total = 0;
  for (const auto& file : listLenses(test::lensDir())) {
    const LensPrescription rx = loadLens(file);
    for (const double n : {0.0, 4.0, 16.0}) {
      Warnings warnings;
      const LensSystem lens(n > 0 ? stopDown(rx, n, warnings) : rx);
      const double filmZ = lens.rearZ() + std::max(1.0, rx.surfaces.back().thickness);
      const double r = lens.rearApertureRadius();
      for (int i = 0; i < 26000; ++i) {
        const Vec3d o{(rng.uniform() - 0.5) * 60, (rng.uniform() - 0.5) * 60, filmZ};
        Vec3d d{(rng.uniform() - 0.5) * 3 * r, (rng.uniform() - 0.5) * 3 * r, lens.rearZ() - filmZ};
        if (i % 97 == 0)
          d = {rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5};  // any direction
        if (i % 1001 == 0) d = {0, 0, 0};
        const auto out =
            lens.traceFromFilm({o, d}, i % 3 == 0 ? 400.0 + 300.0 * rng.uniform() : kWavelengthDNm);
        ++total;
        if (!out) continue;
        ++passed;
        ASSERT_TRUE(isFinite(out->origin) && isFinite(out->direction)) << file;
        ASSERT_NEAR(length(out->direction), 1.0, 1e-9);
        ASSERT_LT(out->direction.z, 0.0);
      }
    }
  }
  EXPECT_GT(total, 1'000'000);
  EXPECT_GT(passed, total / 50);  // the test exercises real passes too
}

// Traces `count` random film rays aimed across the rear aperture in one batch
// and one at a time; returns how many passed, after checking that every
// result is the same, bit for bit.
int expectBatchedEqualsOneAtATime(const LensSystem& lens, int count, unsigned long long seed) {
  SplitMix64 rng(seed);
  std::vector<LensRay> rays;
  const double rear = lens.rearApertureRadius();
  for (int i = 0; i < count; ++i) {
    const auto within = [&](double half) { return (2 * rng.uniform() - 1) * half; };
    const Vec3d film{within(1.3 * rear), within(1.3 * rear), lens.rearZ() + 40};
    const Vec3d aim{within(rear), within(rear), lens.rearZ()};
    rays.push_back({film, aim - film});
  }
  rays[5].direction = {0, 0, 0};  // invalid inputs fail alike
  rays[6].direction = {0, 0, 1};
  // Each ray at its own wavelength too (dispersion), some at the d line.
  std::vector<double> wavelengths;
  for (int i = 0; i < count; ++i)
    wavelengths.push_back(i % 5 == 0 ? kWavelengthDNm : 380.0 + 400.0 * rng.uniform());
  std::vector<std::optional<LensRay>> batched(rays.size()), spectral(rays.size());
  lens.traceFromFilm(rays, batched);
  lens.traceFromFilm(rays, wavelengths, spectral);
  int passed = 0;
  const auto same = [](const Vec3d& a, const Vec3d& b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const std::optional<LensRay> one = lens.traceFromFilm(rays[i]);
    EXPECT_EQ(one.has_value(), batched[i].has_value()) << i;
    const std::optional<LensRay> oneSpectral = lens.traceFromFilm(rays[i], wavelengths[i]);
    EXPECT_EQ(oneSpectral.has_value(), spectral[i].has_value()) << i;
    if (oneSpectral && spectral[i]) {
      EXPECT_TRUE(same(oneSpectral->origin, spectral[i]->origin)) << i;
      EXPECT_TRUE(same(oneSpectral->direction, spectral[i]->direction)) << i;
    }
    if (!one || !batched[i]) continue;
    ++passed;
    EXPECT_TRUE(same(one->origin, batched[i]->origin)) << i;
    EXPECT_TRUE(same(one->direction, batched[i]->direction)) << i;
  }
  return passed;
}

// The batched trace (several rays at once, in vector registers where the CPU
// has them; ctest also runs this with LENSRT_DISABLE_AVX=1) is the one-ray
// trace, bit for bit, whether rays pass or not and whatever the batch length.
TEST(Tracing, BatchedFilmTraceEqualsOneRayAtATime) {
  const LensSystem lens(test::libraryLens("dgauss-50mm"));
  const int passed = expectBatchedEqualsOneAtATime(lens, 203, 7);  // not a multiple of the lane count
  EXPECT_GT(passed, 20);
  EXPECT_LT(passed, 200);  // some blocked too
}

TEST(Tracing, BatchedFilmTraceEqualsOneRayAtATimeForEveryLibraryLens) {
  Warnings warnings;
  for (const auto& entry : std::filesystem::directory_iterator(test::lensDir())) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".lens" && ext != ".json" && ext != ".dat") continue;
    const LensPrescription design = loadLens(entry.path());
    for (const double n : {0.0, 8.0}) {  // wide open, then stopped down
      SCOPED_TRACE(design.name + " f/" + std::to_string(n));
      const LensSystem lens(n > 0 ? stopDown(design, n, warnings) : design);
      // Stopped down, few random rays pass: more of them.
      EXPECT_GT(expectBatchedEqualsOneAtATime(lens, n > 0 ? 20001 : 1001, 3), 5);
    }
  }
}

}  // namespace
}  // namespace lensrt

namespace lensrt {
namespace {

bool sameBits(const Vec3d& a, const Vec3d& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// The chief-ray search traces to the stop by the lens with its rims opened
// and goes on to the film from there (optics/chief_ray.cpp): those pieces
// must be the whole trace's arithmetic, bit for bit, and the real rims must
// be read off the paused trace's hits as the whole trace reads them.
TEST(Tracing, APausedTraceResumesWithTheWholeTracesBits) {
  int cutAfterTheStop = 0;
  for (const char* name : {"dgauss-50mm", "wide-22mm", "fisheye-10mm", "canon-rf50-51mm"}) {
    const LensSystem lens(test::libraryLens(name));
    const LensSystem open = lens.withOpenRims();
    const int stop = lens.paraxial().stopIndex;
    const double front = lens.frontApertureRadius();
    int passed = 0, cutBeforeTheStop = 0;
    for (int i = 0; i < 4000; ++i) {
      // Rays from 1 m toward the entrance pupil's plane, some past the front glass's rim.
      const double u = (i % 63) / 62.0 - 0.5, v = (i / 63 % 63) / 62.0 - 0.5;
      const Vec3d target{2.4 * front * u, 2.4 * front * v, lens.paraxial().entrancePupilZ};
      const Vec3d origin{600.0 * v, -400.0 * u, -1000.0};
      const LensRay ray{origin, target - origin};
      const double wavelength = i % 3 == 0 ? 486.1 : kWavelengthDNm;  // dispersion too
      std::vector<Vec3d> hits, path;
      const auto paused = open.traceFromSceneTo(ray, stop, wavelength, &hits);
      const auto whole = lens.traceFromScene(ray, wavelength, &path);
      if (!paused) {
        EXPECT_FALSE(whole) << name << " " << i;
        continue;
      }
      ASSERT_EQ(hits.size(), std::size_t(stop) + 1);
      const bool held = lens.rimsHold(hits);
      const auto resumed = held ? lens.resumeFromScene(paused.value(), wavelength) : std::nullopt;
      ASSERT_EQ(bool(resumed), bool(whole)) << name << " " << i;
      if (whole) {
        ++passed;
        EXPECT_TRUE(sameBits(resumed->origin, whole->origin) &&
                    sameBits(resumed->direction, whole->direction))
            << name << " " << i;
        for (std::size_t k = 0; k < hits.size(); ++k)
          EXPECT_TRUE(sameBits(hits[k], path[k])) << name << " " << i;
      } else {
        ++(held ? cutAfterTheStop : cutBeforeTheStop);
      }
      // The open lens's own whole trace, resumed.
      const auto openWhole = open.traceFromScene(ray, wavelength);
      const auto openResumed = open.resumeFromScene(paused.value(), wavelength);
      ASSERT_EQ(bool(openResumed), bool(openWhole)) << name << " " << i;
      if (openWhole)
        EXPECT_TRUE(sameBits(openResumed->origin, openWhole->origin) &&
                    sameBits(openResumed->direction, openWhole->direction))
            << name << " " << i;
      // Paused inside the glass of the first element (dispersion's index carried over).
      if (const auto inGlass = lens.traceFromSceneTo(ray, 0, wavelength)) {
        const auto rest = lens.resumeFromScene(*inGlass, wavelength);
        ASSERT_EQ(bool(rest), bool(whole)) << name << " " << i;
        if (whole)
          EXPECT_TRUE(sameBits(rest->origin, whole->origin) && sameBits(rest->direction, whole->direction))
              << name << " " << i;
      }
    }
    // Each case happens: the checks above saw rays pass and rims cut on both sides of the stop.
    EXPECT_GT(passed, 10) << name;
    EXPECT_GT(cutBeforeTheStop, 10) << name;
  }
  EXPECT_GT(cutAfterTheStop, 10);
}

}  // namespace
}  // namespace lensrt
