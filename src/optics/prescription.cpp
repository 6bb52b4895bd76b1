#include "optics/prescription.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/error.h"
#include "optics/paraxial.h"

namespace lensrt {

int LensPrescription::stopIndex() const {
  for (std::size_t i = 0; i < surfaces.size(); ++i)
    if (surfaces[i].isStop) return static_cast<int>(i);
  return -1;
}

double LensPrescription::length() const {
  double z = 0.0;
  for (std::size_t i = 0; i + 1 < surfaces.size(); ++i) z += surfaces[i].thickness;
  return z;
}

LensPrescription LensPrescription::scaled(double factor) const {
  LensPrescription out = *this;
  for (Surface& s : out.surfaces) {
    s.radius *= factor;
    s.thickness *= factor;
    s.apertureDiameter *= factor;
  }
  out.nominalFocalLengthMm *= factor;
  return out;
}

namespace {

// Axial sag of a sphere at height r (signed like the radius); 0 when flat.
double sag(double radius, double r) {
  if (radius == 0.0) return 0.0;
  const double R = std::abs(radius);
  return std::copysign(R - std::sqrt(std::max(0.0, R * R - r * r)), radius);
}

std::string fmtMm(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g mm", v);
  return buf;
}

}  // namespace

void validatePrescription(const LensPrescription& lens) {
  const auto fail = [&](const Surface* s, int index, const std::string& msg) {
    const std::string where = index >= 0 ? "surface " + std::to_string(index + 1) + ": " : "";
    throw InputError(lens.file, where + msg, s ? s->line : 0);
  };
  if (lens.surfaces.empty()) fail(nullptr, -1, "no surfaces");
  if (static_cast<int>(lens.surfaces.size()) > kMaxSurfaces)
    fail(nullptr, -1, "more than " + std::to_string(kMaxSurfaces) + " surfaces: not a lens");
  int stops = 0;
  for (std::size_t k = 0; k < lens.surfaces.size(); ++k) {
    const Surface& s = lens.surfaces[k];
    const int i = static_cast<int>(k);
    for (const double v : {s.radius, s.thickness, s.apertureDiameter, s.medium.nd, s.medium.vd})
      if (!std::isfinite(v)) fail(&s, i, "a number is NaN or infinite");
    if (std::abs(s.radius) > 1e7) fail(&s, i, "radius " + fmtMm(s.radius) + " is absurd (use 0 for flat)");
    if (s.thickness < 0.0) fail(&s, i, "negative thickness " + fmtMm(s.thickness));
    if (s.thickness > kMaxLengthMm) fail(&s, i, "thickness " + fmtMm(s.thickness) + " is absurd");
    if (s.apertureDiameter <= 0.0)
      fail(&s, i, "aperture diameter must be positive, got " + fmtMm(s.apertureDiameter));
    if (s.apertureDiameter > kMaxLengthMm)
      fail(&s, i, "aperture " + fmtMm(s.apertureDiameter) + " is absurd");
    if (s.medium.nd < 1.0 || s.medium.nd > 4.0)
      fail(&s, i, "refractive index " + std::to_string(s.medium.nd) + " is outside [1, 4]");
    if (s.medium.vd < 0.0 || s.medium.vd > 200.0)
      fail(&s, i, "Abbe number " + std::to_string(s.medium.vd) + " is outside [0, 200]");
    if (s.radius != 0.0 && std::abs(s.radius) < s.apertureDiameter / 2.0)
      fail(&s, i,
           "aperture diameter " + fmtMm(s.apertureDiameter) + " is wider than the sphere of radius " +
               fmtMm(s.radius));
    if (s.isStop) {
      ++stops;
      if (stops > 1) fail(&s, i, "a second aperture stop (a lens has exactly one)");
      if (s.radius != 0.0) fail(&s, i, "the aperture stop must be flat (radius 0)");
      const Medium& before = k > 0 ? lens.surfaces[k - 1].medium : Medium{};
      if (before.nd != s.medium.nd) fail(&s, i, "the aperture stop must not change the medium");
    }
  }
  if (stops == 0) fail(nullptr, -1, "no aperture stop (mark one surface as the stop)");
  // Consecutive surfaces must not cut into each other within their clear
  // apertures: the rear one's sag surface stays behind the front one's.
  for (std::size_t k = 0; k + 1 < lens.surfaces.size(); ++k) {
    const Surface& a = lens.surfaces[k];
    const Surface& b = lens.surfaces[k + 1];
    const double rMax = std::min(a.apertureDiameter, b.apertureDiameter) / 2.0;
    constexpr int kSteps = 32;
    for (int j = 0; j <= kSteps; ++j) {
      const double r = rMax * j / kSteps;
      const double gap = a.thickness + sag(b.radius, r) - sag(a.radius, r);
      // 1 micrometre of tolerance: cemented and touching designs are fine.
      if (gap < -1e-3)
        fail(&b, static_cast<int>(k + 1),
             "cuts into the previous surface at height " + fmtMm(r) + " (overlap " + fmtMm(-gap) + ")");
    }
  }
  const double length = lens.length();
  if (length > kMaxLengthMm) fail(nullptr, -1, "total length " + fmtMm(length) + " is absurd");
  // Focus, pupils and every camera model need a focal length; computeParaxial's
  // std::domain_error would otherwise reach the user without the file name.
  try {
    computeParaxial(lens);
  } catch (const std::domain_error& e) {
    fail(nullptr, -1, e.what());
  }
}

}  // namespace lensrt
