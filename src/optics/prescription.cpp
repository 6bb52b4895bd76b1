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

bool LensPrescription::hasAspheres() const {
  return std::any_of(surfaces.begin(), surfaces.end(), [](const Surface& s) { return s.isAspheric(); });
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
    // z'(r) = f z(r / f): the term A r^n becomes A f^(1 - n) r^n.
    double power = factor * factor * factor;  // f^3 for n = 4
    for (double& a : s.aspheric) {
      a /= power;
      power *= factor * factor;
    }
  }
  out.nominalFocalLengthMm *= factor;
  out.closestFocusMm *= factor;
  return out;
}

double Surface::sag(double r) const {
  if (isAspheric()) return profile().sag(r * r).value_or(0.0);
  if (radius == 0.0) return 0.0;
  const double R = std::abs(radius);
  return std::copysign(R - std::sqrt(std::max(0.0, R * R - r * r)), radius);
}

namespace {

// Samples of an asphere's sag across the clear aperture, for the extremes
// (a polynomial profile need not be monotonic).
template <typename F>
void forSagSamples(const Surface& s, F&& f) {
  constexpr int kSteps = 64;
  for (int j = 0; j <= kSteps; ++j) f(s.sag(s.apertureDiameter / 2.0 * j / kSteps));
}

}  // namespace

double Surface::minSag() const {
  if (!isAspheric()) return std::min(0.0, sag(apertureDiameter / 2.0));
  double lowest = 0.0;
  forSagSamples(*this, [&](double z) { lowest = std::min(lowest, z); });
  return lowest;
}

double Surface::maxAbsSag() const {
  if (!isAspheric()) return std::abs(sag(apertureDiameter / 2.0));
  double largest = 0.0;
  forSagSamples(*this, [&](double z) { largest = std::max(largest, std::abs(z)); });
  return largest;
}

namespace {

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
    if (!std::isfinite(s.conic)) fail(&s, i, "the conic constant is NaN or infinite");
    if (std::abs(s.conic) > 1e6) fail(&s, i, "conic constant " + std::to_string(s.conic) + " is absurd");
    for (std::size_t j = 0; j < s.aspheric.size(); ++j)
      if (!std::isfinite(s.aspheric[j]))
        fail(&s, i, "aspheric coefficient A" + std::to_string(4 + 2 * j) + " is NaN or infinite");
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
    if (s.medium.sellmeier) {
      if (s.medium.nd == 1.0) fail(&s, i, "Sellmeier coefficients given for air (n_d = 1)");
      if (const std::string problem = sellmeierProblem(*s.medium.sellmeier); !problem.empty())
        fail(&s, i, problem);
    }
    if (s.isAspheric()) {
      // The sag and its slope must exist over the whole clear aperture, and
      // stay within the lens's size (huge polynomial terms are garbage).
      const AsphereProfile profile = s.profile();
      const double rMax = s.apertureDiameter / 2.0;
      if (!(profile.domainRadius() > rMax))
        fail(&s, i,
             "aperture diameter " + fmtMm(s.apertureDiameter) +
                 " is wider than the conic's domain (diameter " + fmtMm(2.0 * profile.domainRadius()) + ")");
      constexpr int kSteps = 64;
      for (int j = 0; j <= kSteps; ++j) {
        const double r = rMax * j / kSteps;
        const auto z = profile.sag(r * r);
        const auto slope = profile.slopeOverR(r * r);
        if (!z || !slope || !std::isfinite(*z) || !std::isfinite(*slope) || std::abs(*z) > kMaxLengthMm)
          fail(&s, i,
               "the aspheric sag is not finite or absurd within the clear aperture (at height " + fmtMm(r) +
                   ")");
      }
    } else if (s.radius != 0.0 && std::abs(s.radius) < s.apertureDiameter / 2.0)
      fail(&s, i,
           "aperture diameter " + fmtMm(s.apertureDiameter) + " is wider than the sphere of radius " +
               fmtMm(s.radius));
    if (s.isStop) {
      ++stops;
      if (stops > 1) fail(&s, i, "a second aperture stop (a lens has exactly one)");
      if (s.radius != 0.0) fail(&s, i, "the aperture stop must be flat (radius 0)");
      if (s.isAspheric()) fail(&s, i, "the aperture stop must not be aspheric");
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
      const double gap = a.thickness + b.sag(r) - a.sag(r);
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
