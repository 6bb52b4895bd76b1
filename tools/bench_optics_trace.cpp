// Exact-trace cost and a bit-exact fingerprint of its results, for tuning
// LensSystem: film points over a 36x24 mm sensor, pupil points from the exit
// pupil bounds (as the lens camera samples them), traced film -> scene, and a
// few scene -> film. The fingerprint hashes every output bit, so two builds
// agree on it only when they trace identically. Count instructions with
//   valgrind --tool=callgrind --toggle-collect='lensrt::LensSystem::trace*' bench_optics_trace
// which is repeatable on a loaded machine, unlike the CPU time it prints.
// The batched trace (LensSystem::traceFromFilm over a span, as the lens
// camera calls it) is timed too, as a ratio against the one-ray trace, and
// must give the same bits.
//   bench_optics_trace [lens name or file] [--rays N] [--fstop F] [--wavelength NM]
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "core/warnings.h"
#include "optics/exit_pupil.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"
#include "optics/sample_sequence.h"

namespace {

struct Fingerprint {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a
  void add(double v) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    for (int i = 0; i < 8; ++i) h = (h ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211ull;
  }
  void add(const lensrt::LensRay& r) {
    add(r.origin.x), add(r.origin.y), add(r.origin.z);
    add(r.direction.x), add(r.direction.y), add(r.direction.z);
  }
};

}  // namespace

template <typename F>
double bestCpuSeconds(int repeats, F&& f) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const std::clock_t c0 = std::clock();
    f();
    best = std::min(best, static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  return best;
}

int run(int argc, char** argv) {
  std::string name = "dgauss-50mm";
  long rays = 200000;
  double fNumber = 4.0, wavelength = lensrt::kWavelengthDNm;
  bool uniform = false;  // pupil points uniform over the rear aperture's square instead of the bounds
  std::string dump;      // write every result (pass flag, origin, direction) to compare builds
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rays" && i + 1 < argc)
      rays = std::atol(argv[++i]);
    else if (a == "--fstop" && i + 1 < argc)
      fNumber = std::atof(argv[++i]);
    else if (a == "--wavelength" && i + 1 < argc)
      wavelength = std::atof(argv[++i]);
    else if (a == "--uniform")
      uniform = true;
    else if (a == "--dump" && i + 1 < argc)
      dump = argv[++i];
    else if (a == "-h" || a == "--help") {
      std::printf(
          "usage: bench_optics_trace [LENS] [--rays N] [--fstop F] [--wavelength NM] [--uniform] [--dump "
          "FILE]\n");
      return 0;
    } else if (a.starts_with("-")) {
      std::fprintf(stderr, "bench_optics_trace: unknown option %s (see --help)\n", a.c_str());
      return 2;
    } else
      name = a;
  }
  lensrt::Warnings warnings;
  const auto design = lensrt::loadLens(lensrt::findLens(name, LENSRT_LENS_DIR));
  const lensrt::LensSystem lens(fNumber > 0 ? lensrt::stopDown(design, fNumber, warnings) : design);
  const double filmZ = lens.rearZ() + lensrt::focusFilmDistance(lens, 2000.0);
  const lensrt::ExitPupilBounds bounds(lens, filmZ, 21.7);

  // Samples first, so the timed loop holds only the trace.
  std::vector<lensrt::LensRay> in;
  in.reserve(rays);
  lensrt::SplitMix64 rng(11);
  while (static_cast<long>(in.size()) < rays) {
    const lensrt::Vec2d f{(rng.uniform() - 0.5) * 36.0, (rng.uniform() - 0.5) * 24.0};
    if (uniform) {
      const double r = lens.rearApertureRadius();
      const lensrt::Vec3d o{f.x, f.y, filmZ};
      in.push_back(
          {o, lensrt::Vec3d{(rng.uniform() - 0.5) * 2 * r, (rng.uniform() - 0.5) * 2 * r, lens.rearZ()} - o});
      continue;
    }
    const auto s = bounds.sample(f, {rng.uniform(), rng.uniform()});
    if (!s) continue;
    const lensrt::Vec3d o{f.x, f.y, filmZ};
    in.push_back({o, s->point - o});
  }
  Fingerprint fp;
  long passed = 0;
  const double seconds = bestCpuSeconds(3, [&] {
    fp = {}, passed = 0;
    for (const auto& r : in) {
      const auto out = lens.traceFromFilm(r, wavelength);
      if (out) ++passed, fp.add(*out);
    }
  });
  // The batched trace exists for the d line only.
  std::optional<double> batchedSeconds;
  bool batchedSameBits = true;
  if (wavelength == lensrt::kWavelengthDNm) {
    std::vector<std::optional<lensrt::LensRay>> out(in.size());
    batchedSeconds = bestCpuSeconds(3, [&] { lens.traceFromFilm(in, out); });
    Fingerprint batched;
    for (const auto& o : out)
      if (o) batched.add(*o);
    batchedSameBits = batched.h == fp.h;
  }
  if (!dump.empty()) {
    std::FILE* file = std::fopen(dump.c_str(), "w");
    for (const auto& r : in) {
      const auto out = lens.traceFromFilm(r, wavelength);
      const lensrt::LensRay v = out.value_or(lensrt::LensRay{});
      std::fprintf(file, "%d %.17g %.17g %.17g %.17g %.17g %.17g\n", out.has_value(), v.origin.x, v.origin.y,
                   v.origin.z, v.direction.x, v.direction.y, v.direction.z);
    }
    std::fclose(file);
  }
  // The reverse direction and the path output, checked on a subset.
  std::vector<lensrt::Vec3d> path;
  for (long i = 0; i < rays / 10; ++i) {
    path.clear();
    const auto out = lens.traceFromFilm(in[i], wavelength, &path);
    if (!out) continue;
    for (const auto& p : path) fp.add(p.x), fp.add(p.y), fp.add(p.z);
    const auto back = lens.traceFromScene({out->origin, -out->direction}, wavelength);
    if (back) fp.add(*back);
  }
  std::printf("%s f/%g %.1f nm: %ld rays, %.1f%% pass, %.1f ns/ray CPU, fingerprint %016llx\n",
              design.name.c_str(), fNumber, wavelength, rays, 100.0 * passed / rays, 1e9 * seconds / rays,
              static_cast<unsigned long long>(fp.h));
  if (batchedSeconds)
    std::printf("batched (%zu lanes): %.1f ns/ray CPU, %.2fx the one-ray trace, %s\n",
                lensrt::LensSystem::kTraceLanes, 1e9 * *batchedSeconds / rays, seconds / *batchedSeconds,
                batchedSameBits ? "same bits" : "DIFFERENT BITS");
  return batchedSameBits ? 0 : 1;
}

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_optics_trace: error: %s\n", e.what());
    return 1;
  }
}
