#include "optics/distortion.h"

#include <algorithm>
#include <cmath>

#include "optics/paraxial.h"

namespace lensrt {
namespace {

constexpr double kDeg = kPi / 180.0;
constexpr double kMaxFieldDeg = 89.5;  // scene rays must travel toward +z

// Most negative z the front surface reaches within its clear aperture.
double frontmostZ(const LensSystem& lens) {
  return lens.prescription().surfaces.front().minSag();
}

// Half-width of the aim-plane scan: wide enough for any passing ray, since a
// passing ray crosses z = 0 no farther out than the front aperture plus the
// slope times the depth of the front cap or the entrance pupil.
double aimScanHalfWidth(const LensSystem& lens, const FieldPoint& field) {
  const Surface& s = lens.prescription().surfaces.front();
  const double a = s.apertureDiameter / 2.0;
  const double sag = s.maxAbsSag();
  const double depth = std::max(sag, std::abs(lens.paraxial().entrancePupilZ)) + 1.0;
  return 1.3 * a + std::abs(std::tan(field.angleDeg * kDeg)) * depth;
}

bool passes(const LensSystem& lens, const FieldPoint& field, double x, double wavelengthNm) {
  return lens.traceFromScene(fieldRay(lens, field, {x, 0.0}), wavelengthNm).has_value();
}

// Bisect between a failing and a passing aim to find the edge of the band.
double refineEdge(const LensSystem& lens, const FieldPoint& field, double fail, double pass, double wl) {
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (fail + pass);
    (passes(lens, field, mid, wl) ? pass : fail) = mid;
  }
  return pass;
}

// Stop-crossing x of a meridional ray, or nullopt when the ray is blocked.
std::optional<double> stopX(const LensSystem& lens, const FieldPoint& field, double x, double wl) {
  std::vector<Vec3d> path;
  if (!lens.traceFromScene(fieldRay(lens, field, {x, 0.0}), wl, &path)) return std::nullopt;
  return path[lens.paraxial().stopIndex].x;
}

}  // namespace

LensRay fieldRay(const LensSystem& lens, const FieldPoint& field, Vec2d aim) {
  const double theta = field.angleDeg * kDeg;
  const Vec3d target{aim.x, aim.y, 0.0};
  if (std::isinf(field.objectDistanceMm)) {
    // The object lies toward +x, so its light travels toward -x.
    const Vec3d d{-std::sin(theta), 0.0, std::cos(theta)};
    const double startZ = frontmostZ(lens) - 1.0;
    return {target + d * (startZ / d.z), d};
  }
  const double epZ = lens.paraxial().entrancePupilZ;
  const Vec3d object{field.objectDistanceMm * std::tan(theta), 0.0, epZ - field.objectDistanceMm};
  return {object, normalize(target - object)};
}

std::optional<AimInterval> meridionalPassBand(const LensSystem& lens, const FieldPoint& field,
                                              double wavelengthNm) {
  double lo = -aimScanHalfWidth(lens, field), hi = -lo;
  // A coarse scan, then a finer one around what passed: the band may be much
  // narrower than the scan range (fisheye fields near 90 degrees).
  for (int pass = 0; pass < 2; ++pass) {
    const int n = 1001;
    const double step = (hi - lo) / (n - 1);
    int first = -1, last = -1;
    for (int i = 0; i < n; ++i)
      if (passes(lens, field, lo + step * i, wavelengthNm)) {
        if (first < 0) first = i;
        last = i;
      }
    if (first < 0) return std::nullopt;
    const double passLo = lo + step * first, passHi = lo + step * last;
    if (pass == 1 || last - first > 100) {
      const double a = first > 0 ? refineEdge(lens, field, passLo - step, passLo, wavelengthNm) : passLo;
      const double b = last < n - 1 ? refineEdge(lens, field, passHi + step, passHi, wavelengthNm) : passHi;
      return AimInterval{a, b};
    }
    lo = passLo - 2.0 * step;
    hi = passHi + 2.0 * step;
  }
  return std::nullopt;
}

std::optional<double> chiefRayAim(const LensSystem& lens, const FieldPoint& field, double wavelengthNm) {
  const auto band = meridionalPassBand(lens, field, wavelengthNm);
  if (!band) return std::nullopt;
  // The stop height varies monotonically across a passing band: find the
  // sign change on a grid, then bisect.
  const int n = 41;
  std::optional<double> prevX, prevS;
  for (int i = 0; i < n; ++i) {
    const double x = band->lo + (band->hi - band->lo) * i / (n - 1);
    const auto s = stopX(lens, field, x, wavelengthNm);
    if (!s) {
      prevX.reset();
      continue;
    }
    if (*s == 0.0) return x;
    if (prevX && (*s > 0.0) != (*prevS > 0.0)) {
      double a = *prevX, b = x;
      const bool aPositive = *prevS > 0.0;
      for (int k = 0; k < 50; ++k) {
        const double mid = 0.5 * (a + b);
        const auto sm = stopX(lens, field, mid, wavelengthNm);
        if (!sm) return std::nullopt;
        ((*sm > 0.0) == aPositive ? a : b) = mid;
      }
      return 0.5 * (a + b);
    }
    prevX = x;
    prevS = s;
  }
  return std::nullopt;
}

std::optional<double> chiefRayImageHeight(const LensSystem& lens, const FieldPoint& field,
                                          double filmDistanceMm, double wavelengthNm) {
  const auto aim = chiefRayAim(lens, field, wavelengthNm);
  if (!aim) return std::nullopt;
  const auto out = lens.traceFromScene(fieldRay(lens, field, {*aim, 0.0}), wavelengthNm);
  if (!out) return std::nullopt;
  const double filmZ = lens.rearZ() + filmDistanceMm;
  return out->origin.x + out->direction.x * (filmZ - out->origin.z) / out->direction.z;
}

namespace {

// Scan field angles upward until the chief ray reaches `height`; returns the
// bracketing angles (or the largest traceable angle when never reached).
struct HeightSearch {
  double below = 0.0, above = 0.0;
  bool reached = false;
};
HeightSearch bracketHeight(const LensSystem& lens, double objectDistanceMm, double film, double height) {
  HeightSearch h;
  const double step = 1.0;
  for (double a = step; a <= kMaxFieldDeg + 1e-9; a += step) {
    const auto y = chiefRayImageHeight(lens, {a, objectDistanceMm}, film);
    if (!y) break;
    if (std::abs(*y) >= height) {
      h.above = a;
      h.reached = true;
      return h;
    }
    h.below = a;
  }
  return h;
}

}  // namespace

FieldLimit fieldForImageHeight(const LensSystem& lens, double objectDistanceMm, double filmDistanceMm,
                               double imageHeightMm) {
  FieldLimit limit;
  if (imageHeightMm <= 0.0) return limit;
  const HeightSearch h = bracketHeight(lens, objectDistanceMm, filmDistanceMm, imageHeightMm);
  // Bisect either on the height or, when the target is out of reach, on the
  // last angle whose chief ray still passes.
  double a = h.below, b = h.reached ? h.above : std::min(h.below + 1.0, kMaxFieldDeg);
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (a + b);
    const auto y = chiefRayImageHeight(lens, {mid, objectDistanceMm}, filmDistanceMm);
    (y && std::abs(*y) < imageHeightMm ? a : b) = mid;
  }
  limit.reachedTarget = h.reached;
  limit.angleDeg = h.reached ? 0.5 * (a + b) : a;
  limit.imageHeightMm =
      std::abs(chiefRayImageHeight(lens, {limit.angleDeg, objectDistanceMm}, filmDistanceMm).value_or(0.0));
  return limit;
}

std::optional<double> fieldAngleForImageHeight(const LensSystem& lens, double objectDistanceMm,
                                               double filmDistanceMm, double imageHeightMm) {
  const FieldLimit limit = fieldForImageHeight(lens, objectDistanceMm, filmDistanceMm, imageHeightMm);
  if (imageHeightMm > 0.0 && !limit.reachedTarget) return std::nullopt;
  return limit.angleDeg;
}

std::vector<DistortionPoint> distortionCurve(const LensSystem& lens, double objectDistanceMm,
                                             double filmDistanceMm, double maxImageHeightMm, int points) {
  const double maxAngle =
      fieldForImageHeight(lens, objectDistanceMm, filmDistanceMm, maxImageHeightMm).angleDeg;
  const ParaxialData& p = lens.paraxial();
  const double scale =
      std::isinf(objectDistanceMm)
          ? p.efl
          : std::abs(paraxialConjugate(p, objectDistanceMm).magnification) * objectDistanceMm;
  std::vector<DistortionPoint> curve;
  for (int i = 0; i < std::max(points, 2); ++i) {
    DistortionPoint d;
    d.fieldAngleDeg = maxAngle * i / (std::max(points, 2) - 1);
    if (i == 0) {
      curve.push_back(d);
      continue;
    }
    const auto y = chiefRayImageHeight(lens, {d.fieldAngleDeg, objectDistanceMm}, filmDistanceMm);
    if (!y) continue;
    d.realHeightMm = std::abs(*y);
    d.paraxialHeightMm = scale * std::tan(d.fieldAngleDeg * kDeg);
    d.percent = 100.0 * (d.realHeightMm - d.paraxialHeightMm) / d.paraxialHeightMm;
    curve.push_back(d);
  }
  return curve;
}

}  // namespace lensrt
