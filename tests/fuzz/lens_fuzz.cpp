// libFuzzer target for one lens reader (LENSRT_LENS_FORMAT: dat, lens, json or zmx),
// followed by everything a valid prescription goes through before rendering:
// validation, the traced system, focus, stop-down, exit pupil bounds, rays.
// Only InputError may escape the library; any other exception, a crash, a
// sanitizer report or a non-finite traced ray is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/constants.h"
#include "core/error.h"
#include "core/warnings.h"
#include "fuzz/fuzz_check.h"
#include "optics/exit_pupil.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"
#include "optics/lens_system.h"

namespace {

using namespace lensrt;

LensPrescription parse(std::string_view text) {
  const std::string format = LENSRT_LENS_FORMAT;
  const std::string file = "fuzz." + format;
  if (format == "dat") return parsePbrtLens(text, file);
  if (format == "lens") return parseTableLens(text, file);
  if (format == "zmx") return parseZemaxLens(text, file);
  return parseJsonLens(text, file);
}

void checkRay(const std::optional<LensRay>& r) {
  if (!r) return;
  LENSRT_FUZZ_CHECK(isFinite(r->origin) && isFinite(r->direction));
  LENSRT_FUZZ_CHECK(std::abs(length(r->direction) - 1.0) < 1e-6);
}

// A few deterministic rays from the film toward the lens and back.
void traceSome(const LensSystem& lens, double filmZ) {
  const double r = lens.rearApertureRadius();
  for (int i = 0; i < 16; ++i) {
    const double a = (i % 4 - 1.5) / 1.5, b = (i / 4 - 1.5) / 1.5;
    const Vec3d film{a * 10.0, b * 10.0, filmZ};
    const Vec3d target{b * r, a * r, lens.rearZ()};
    checkRay(lens.traceFromFilm({film, target - film}, 400.0 + 20.0 * i));
    checkRay(lens.traceFromScene({Vec3d{a * r, b * r, -100.0}, Vec3d{0.01 * a, 0.01 * b, 1.0}}));
  }
}

void exercise(const LensPrescription& rx) {
  validatePrescription(rx);
  const LensSystem lens(rx);
  double filmDistance = 0.0;
  try {
    filmDistance = focusFilmDistance(lens, kInfinity);
  } catch (const InputError&) {
    filmDistance = 1.0;  // cannot focus (afocal, virtual image): still trace
  }
  LENSRT_FUZZ_CHECK(std::isfinite(filmDistance) && filmDistance > 0.0);
  traceSome(lens, lens.rearZ() + filmDistance);
  Warnings warnings;
  const LensSystem stopped(stopDown(rx, 8.0, warnings));
  const double filmZ = stopped.rearZ() + filmDistance;
  traceSome(stopped, filmZ);
  const ExitPupilBounds bounds(stopped, filmZ, 21.6, 4);
  for (int i = 0; i < 8; ++i) {
    const auto s = bounds.sample({i * 3.0, 0.0}, {(i + 0.5) / 8.0, 0.37});
    if (!s) continue;
    LENSRT_FUZZ_CHECK(isFinite(s->point) && std::isfinite(s->pdf) && s->pdf > 0.0);
    checkRay(stopped.traceFromFilm({Vec3d{i * 3.0, 0.0, filmZ}, s->point - Vec3d{i * 3.0, 0.0, filmZ}}));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    exercise(parse(std::string_view(reinterpret_cast<const char*>(data), size)));
  } catch (const InputError&) {
    // Rejected with a message: the expected outcome for most inputs.
  }
  return 0;
}
