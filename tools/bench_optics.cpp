// Optics figures that must not live in unit tests because they are timings:
// exit pupil bounds construction time (target < 0.2 s on 2 cores for an
// 11-surface lens), their efficiency (share of sampled rays that pass;
// target >= 90% for dgauss-50mm at f/2 over 36x24 mm, pbrt-v4's boxes ~72%),
// exact tracing throughput, and the chief-ray projection's cost (what the
// flow AOV pays per sample): its table, a point projected, a film point's ray.
//   bench_optics [lens names...]   (default: the whole library)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "core/constants.h"
#include "core/warnings.h"
#include "optics/chief_ray.h"
#include "optics/exit_pupil.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"
#include "optics/sample_sequence.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

void bench(const lensrt::LensPrescription& design, double fNumber) {
  lensrt::Warnings warnings;
  const lensrt::LensSystem lens(fNumber > 0 ? lensrt::stopDown(design, fNumber, warnings) : design);
  const double film = lensrt::focusFilmDistance(lens, lensrt::kInfinity);
  const double halfDiagonal = std::hypot(36.0, 24.0) / 2.0;
  // Wall time depends on how busy the machine is; CPU time (all threads)
  // divided by the cores used is the figure for an idle 2-core machine.
  std::vector<double> times, cpuTimes;
  for (int i = 0; i < 5; ++i) {
    const auto t0 = Clock::now();
    const std::clock_t c0 = std::clock();
    const lensrt::ExitPupilBounds bounds(lens, lens.rearZ() + film, halfDiagonal);
    cpuTimes.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    times.push_back(seconds(t0, Clock::now()));
  }
  std::sort(times.begin(), times.end());
  std::sort(cpuTimes.begin(), cpuTimes.end());
  const lensrt::ExitPupilBounds bounds(lens, lens.rearZ() + film, halfDiagonal);
  const auto eff = lensrt::measurePupilEfficiency(lens, bounds, 36.0, 24.0, 200000);
  // The same bounds as an axis-aligned box (pbrt-v4's shape), for comparison.
  lensrt::SplitMix64 boxRng(3);
  long boxSampled = 0, boxPassed = 0;
  for (int i = 0; i < 100000; ++i) {
    const lensrt::Vec2d f{(boxRng.uniform() - 0.5) * 36, (boxRng.uniform() - 0.5) * 24};
    const auto poly = bounds.polygon(f);
    if (poly.empty()) continue;
    double x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
    for (const auto& v : poly)
      x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
    const lensrt::Vec3d o{f.x, f.y, bounds.filmZ()};
    const lensrt::Vec3d p{x0 + (x1 - x0) * boxRng.uniform(), y0 + (y1 - y0) * boxRng.uniform(),
                          bounds.planeZ()};
    ++boxSampled;
    boxPassed += lens.traceFromFilm({o, p - o}).has_value();
  }
  // Tracing throughput: rays from film points toward the rear element.
  lensrt::SplitMix64 rng(7);
  const int n = 1000000;
  int passed = 0;
  const std::clock_t c0 = std::clock();  // CPU time: this loop is single-threaded
  for (int i = 0; i < n; ++i) {
    const lensrt::Vec3d o{(rng.uniform() - 0.5) * 36, (rng.uniform() - 0.5) * 24, lens.rearZ() + film};
    const double r = lens.rearApertureRadius();
    const lensrt::Vec3d p{(rng.uniform() - 0.5) * 2 * r, (rng.uniform() - 0.5) * 2 * r, lens.rearZ()};
    passed += lens.traceFromFilm({o, p - o}).has_value();
  }
  const double traceS = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  std::printf(
      "%-24s f/%-5.3g surfaces %2d  bounds build %6.1f ms wall, %6.1f ms CPU (medians of 5)  efficiency "
      "%5.1f%% (as a bounding box: %4.1f%%)  "
      "(%ld film samples outside the image circle)  trace %5.1f ns/ray CPU (%4.1f%% pass)\n",
      design.name.c_str(), lens.paraxial().fNumber, lens.surfaceCount(), 1e3 * times[2], 1e3 * cpuTimes[2],
      100.0 * eff.efficiency(), 100.0 * boxPassed / std::max(1L, boxSampled), eff.empty, 1e9 * traceS / n,
      100.0 * passed / n);

  // The projection: points spread over the field 3 m away, film points over the frame.
  const std::clock_t t0 = std::clock();
  const lensrt::ChiefRays chief(lens, lens.rearZ() + film);
  const double tableS = static_cast<double>(std::clock() - t0) / CLOCKS_PER_SEC;
  const int points = 200000;
  const double reach = 3000.0 * std::tan(lensrt::kPi / 180.0 * 0.9 * chief.tableFieldDeg());
  double sink = 0.0;
  const std::clock_t p0 = std::clock();
  for (int i = 0; i < points; ++i) {
    const double r = reach * std::sqrt(rng.uniform()), phi = 2.0 * lensrt::kPi * rng.uniform();
    const lensrt::ChiefRayImage image = chief.ofPoint({r * std::cos(phi), r * std::sin(phi), -3000.0});
    sink += image.status == lensrt::ChiefRayStatus::Passes ? image.film.x : 0.0;
  }
  const double projectS = static_cast<double>(std::clock() - p0) / CLOCKS_PER_SEC;
  const std::clock_t u0 = std::clock();
  for (int i = 0; i < points; ++i) {
    const lensrt::ChiefRayToScene ray =
        chief.ofFilmPoint({(rng.uniform() - 0.5) * 36, (rng.uniform() - 0.5) * 24});
    sink += ray.status == lensrt::ChiefRayStatus::Passes ? ray.ray.direction.x : 0.0;
  }
  const double unprojectS = static_cast<double>(std::clock() - u0) / CLOCKS_PER_SEC;
  std::printf(
      "%-24s chief rays: table %.2f ms (to %.1f deg), project %.0f ns/point, unproject %.0f ns/point CPU%s\n",
      "", 1e3 * tableS, chief.tableFieldDeg(), 1e9 * projectS / points, 1e9 * unprojectS / points,
      sink == 12345.0 ? " " : "");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> names(argv + 1, argv + argc);
  if (names.empty())
    for (const auto& p : lensrt::listLenses(LENSRT_LENS_DIR)) names.push_back(p.stem().string());
  for (const std::string& name : names) {
    const auto design = lensrt::loadLens(lensrt::findLens(name, LENSRT_LENS_DIR));
    bench(design, 0.0);  // wide open (dgauss-50mm: f/2.03, so an f/2 row would repeat it)
    if (name == "dgauss-50mm") bench(design, 2.8), bench(design, 8.0);
  }
  return 0;
}
