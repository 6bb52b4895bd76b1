// No NaN, no Inf from any camera model: a million random camera rays (film
// positions slightly beyond the raster, lens samples at the edges of [0,1),
// wavelengths across the visible) through every library lens at several
// f-numbers and focus distances, for the full lens and the thick and thin
// models derived from it. Each ray is either blocked or finite with a unit
// direction and a finite, non-negative weight. (tests/optics checks the raw
// LensSystem trace; this covers the cameras' sampling and weights on top.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "camera/lens_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "core/error.h"
#include "core/transform.h"
#include "core/warnings.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

// SplitMix64: a small deterministic generator for the test's own samples.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  double uniform() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

struct Tally {
  long traced = 0;
  long passed = 0;
};

// Lens samples include the exact corners of [0,1)^2, where mappings to disks
// and polygons divide by small numbers.
float edgy(Random& rng) {
  const double u = rng.uniform();
  if (u < 0.02) return 0.0f;
  if (u < 0.04) return std::nextafter(1.0f, 0.0f);
  if (u < 0.05) return 0.5f;
  return static_cast<float>(rng.uniform());
}

void shoot(const Camera& camera, int rays, Random& rng, Tally& tally, const std::string& what) {
  const FilmGeometry& film = camera.film();
  for (int i = 0; i < rays; ++i) {
    CameraSample s;
    s.film = Vec2f(static_cast<float>((rng.uniform() * 1.02 - 0.01) * film.width),
                   static_cast<float>((rng.uniform() * 1.02 - 0.01) * film.height));
    if (i % 50 == 0) s.film = Vec2f(film.width * 0.5f, film.height * 0.5f);  // the exact centre
    s.lens = Vec2f(edgy(rng), edgy(rng));
    s.wavelengthNm = static_cast<float>(380.0 + 400.0 * rng.uniform());
    const std::optional<CameraRay> r = camera.generateRay(s);
    ++tally.traced;
    if (!r) continue;
    ++tally.passed;
    ASSERT_TRUE(isFinite(r->ray.origin)) << what << " film " << s.film.x << "," << s.film.y;
    ASSERT_TRUE(isFinite(r->ray.direction)) << what << " film " << s.film.x << "," << s.film.y;
    ASSERT_NEAR(length(r->ray.direction), 1.0f, 1e-4f) << what;
    ASSERT_TRUE(std::isfinite(r->weight) && r->weight >= 0.0f) << what << " weight " << r->weight;
  }
}

TEST(CameraRays, NoNaNOrInfFromAnyModelAndLibraryLens) {
  const auto lenses = listLenses(std::filesystem::path(LENSRT_SOURCE_DIR) / "lenses");
  ASSERT_FALSE(lenses.empty());
  // A camera placed off the origin and turned, as glTF nodes place it.
  const Transform place =
      Transform::translate({1.5, -2.0, 3.0}) * Transform::rotateQuaternion(0.1, 0.7, 0.1, 0.7);
  const FilmGeometry film{48, 32, 36.0, 24.0};
  const std::vector<double> fNumbers{0.0, 4.0, 11.0, 22.0};  // 0: wide open
  const long kLensRays = 1'000'000;
  const int perConfig = static_cast<int>(kLensRays / static_cast<long>(lenses.size() * fNumbers.size())) + 1;
  Random rng(2024);
  Tally full, thick, thin;
  for (const auto& file : lenses) {
    const LensPrescription rx = loadLens(file);
    const LensSystem system(rx);
    const ParaxialData p = computeParaxial(rx);
    // Infinity, and a close focus a bit beyond the closest the lens allows.
    const double closeMetres = std::max(0.05, 3.0 * closestFocusDistanceMm(system) / 1000.0);
    int config = 0;
    for (const double n : fNumbers) {
      const double focus = (config++ % 2 == 0) ? kInfinity : closeMetres;
      const std::string what = rx.name + " f/" + std::to_string(n) + " focus " + std::to_string(focus) + " m";
      Warnings warnings;
      LensCameraParams lp;
      lp.fNumber = n;
      lp.focusMetres = focus;
      lp.dispersion = config % 3 != 0;
      const LensCamera lensCamera(place, film, rx, lp, Exposure{}, warnings);
      shoot(lensCamera, perConfig, rng, full, "lens " + what);
      if (HasFatalFailure()) return;

      const double widest = lensCamera.fNumber();
      const ThickLensCamera thickCamera(place, film, thickLensFromParaxial(p, std::max(n, widest), focus));
      shoot(thickCamera, perConfig / 4, rng, thick, "thick " + what);
      if (HasFatalFailure()) return;

      ThinLensParams tp;
      tp.focalLengthMm = p.efl;
      tp.fNumber = std::max(n, widest);
      tp.focusMetres = focus;
      const ThinLensCamera thinCamera(place, film, tp);
      shoot(thinCamera, perConfig / 4, rng, thin, "thin " + what);
      if (HasFatalFailure()) return;
    }
  }
  EXPECT_GE(full.traced, kLensRays);
  // The test must exercise real passes, not only blocked rays.
  EXPECT_GT(full.passed, full.traced / 10);
  EXPECT_GT(thick.passed, thick.traced / 2);
  EXPECT_GT(thin.passed, thin.traced / 2);
}

}  // namespace
}  // namespace lensrt
