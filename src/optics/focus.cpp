#include "optics/focus.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/constants.h"
#include "core/error.h"

namespace lensrt {
namespace {

std::string metres(double mm) {
  if (std::isinf(mm)) return "infinity";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g m", mm / 1000.0);
  return buf;
}

// Most negative z the front surface reaches within its clear aperture.
double frontmostZ(const LensSystem& lens) {
  return lens.prescription().surfaces.front().minSag();
}

// Where an exactly traced ray from the on-axis object, aimed at height h in
// the entrance pupil, crosses the axis behind the lens; NaN when blocked.
double axisCrossing(const LensSystem& lens, double objectZ, double h) {
  const ParaxialData& p = lens.paraxial();
  LensRay ray;
  if (std::isinf(objectZ)) {
    ray.origin = {h, 0.0, frontmostZ(lens) - 1.0};
    ray.direction = {0.0, 0.0, 1.0};
  } else {
    ray.origin = {0.0, 0.0, objectZ};
    ray.direction = Vec3d{h, 0.0, p.entrancePupilZ} - ray.origin;
  }
  const auto out = lens.traceFromScene(ray);
  if (!out || out->direction.x == 0.0) return std::nan("");
  return out->origin.z - out->origin.x * out->direction.z / out->direction.x;
}

}  // namespace

double nearestRealImageDistanceMm(const LensSystem& lens) {
  const ParaxialData& p = lens.paraxial();
  return std::max(p.entrancePupilZ - p.frontFocalZ, p.entrancePupilZ - frontmostZ(lens));
}

double closestFocusDistanceMm(const LensSystem& lens) {
  const ParaxialData& p = lens.paraxial();
  // Nearer than a real lens focuses, the film extension runs away toward
  // infinity and the pictures degenerate: the design's own limit applies, or
  // else magnification 1:1 (the object 2f in front of the front principal
  // plane), where a macro lens stops.
  const double stated = lens.prescription().closestFocusMm > 0
                            ? lens.prescription().closestFocusMm
                            : p.entrancePupilZ - (p.frontPrincipalZ - 2.0 * p.efl);
  return std::max(nearestRealImageDistanceMm(lens), stated);
}

double focusFilmDistance(const LensSystem& lens, double objectDistanceMm) {
  const ParaxialData& p = lens.paraxial();
  const std::string& name = lens.prescription().name;
  if (std::isnan(objectDistanceMm) || objectDistanceMm <= 0.0)
    throw InputError(name, "focus distance must be positive");
  const double objectZ = std::isinf(objectDistanceMm) ? -kInfinity : p.entrancePupilZ - objectDistanceMm;
  Conjugate estimate;
  try {
    if (!std::isinf(objectZ) && objectZ >= frontmostZ(lens)) throw std::domain_error("inside the lens");
    estimate = paraxialConjugate(p, objectDistanceMm);
  } catch (const std::domain_error&) {
    throw InputError(name, "cannot focus at " + metres(objectDistanceMm) +
                               " from the entrance pupil: closer than the lens can focus (needs more than " +
                               metres(nearestRealImageDistanceMm(lens)) + ")");
  }
  // Refine on real rays: the axis crossing z(h) = z0 + a h^2 + O(h^4);
  // Richardson extrapolation of two small heights gives the paraxial z0 of
  // the real surfaces, free of the matrix model's rounding.
  const double r = p.entrancePupilDiameter / 2.0;
  const double h1 = 0.01 * r, h2 = 0.02 * r;
  const double z1 = axisCrossing(lens, objectZ, h1), z2 = axisCrossing(lens, objectZ, h2);
  double imageZ = estimate.imageZ;
  if (std::isfinite(z1) && std::isfinite(z2)) imageZ = (z1 * h2 * h2 - z2 * h1 * h1) / (h2 * h2 - h1 * h1);
  const double film = imageZ - lens.rearZ();
  if (!(film > 0.0))
    throw InputError(name,
                     "cannot focus at " + metres(objectDistanceMm) + ": the image falls inside the lens");
  return film;
}

LensPrescription stopDown(const LensPrescription& lens, double fNumber, Warnings& warnings) {
  if (!(fNumber > 0.0) || !std::isfinite(fNumber))
    throw InputError(lens.name, "f-number must be a positive number");
  const ParaxialData p = computeParaxial(lens);
  LensPrescription out = lens;
  if (fNumber < p.fNumber * (1.0 - 1e-9)) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s: f/%g is wider than the lens allows; using its widest aperture f/%.3g",
                  lens.name.c_str(), fNumber, p.fNumber);
    warnings.warn(buf);
    return out;
  }
  // The entrance pupil is the stop's paraxial image: its diameter scales with the stop's.
  out.surfaces[p.stopIndex].apertureDiameter *= p.fNumber / fNumber;
  return out;
}

}  // namespace lensrt
