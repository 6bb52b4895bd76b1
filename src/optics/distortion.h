// Field rays, the real chief ray and distortion.
//
// A field point is an object seen at an angle from the axis, measured at the
// entrance pupil's centre, in the meridional (x-z) plane; the object lies
// `objectDistanceMm` in front of the entrance pupil (kInfinity allowed, as in
// focus.h). Scene rays from it are named by where they (or their straight
// extension) cross the plane z = 0 of the first vertex: the "aim plane".
//
// Distortion is the real chief ray's image height against the paraxial one:
//   D = 100 (y_real - y_paraxial) / y_paraxial  [%],
// y_paraxial = efl tan(theta) for an object at infinity, |m| D tan(theta)
// for an object at distance D with lateral magnification m. The chief ray is
// the real ray through the centre of the aperture stop (not the paraxial
// entrance pupil's centre: pupil aberration moves it). Negative = barrel.
#pragma once

#include <optional>
#include <vector>

#include "core/constants.h"
#include "core/vec.h"
#include "optics/glass.h"
#include "optics/lens_system.h"

namespace lensrt {

struct FieldPoint {
  double angleDeg = 0.0;                // from the axis, toward +x in object space; |angle| < 90
  double objectDistanceMm = kInfinity;  // in front of the entrance pupil
};

// The scene ray of a field point through (x, y) on the aim plane, starting
// in front of the lens (direction.z > 0).
LensRay fieldRay(const LensSystem& lens, const FieldPoint& field, Vec2d aim);

// Aim-plane x range [lo, hi] of the meridional rays (y = 0) of a field that
// pass the whole lens, edges refined to ~1e-6 of the scan range; nullopt
// when no ray passes.
struct AimInterval {
  double lo = 0.0, hi = 0.0;
};
std::optional<AimInterval> meridionalPassBand(const LensSystem& lens, const FieldPoint& field,
                                              double wavelengthNm = kWavelengthDNm);

// Aim-plane x of the field's real chief ray (crossing the stop's centre);
// nullopt when no passing ray of the field crosses it.
std::optional<double> chiefRayAim(const LensSystem& lens, const FieldPoint& field,
                                  double wavelengthNm = kWavelengthDNm);

// Signed image height (film x, mm; negative for a positive angle: the image
// is inverted) of the chief ray on the film plane z = rearZ + filmDistance.
std::optional<double> chiefRayImageHeight(const LensSystem& lens, const FieldPoint& field,
                                          double filmDistanceMm, double wavelengthNm = kWavelengthDNm);

// The field angle whose chief ray lands at image height `imageHeightMm` (a
// magnitude), or when no angle below 89.5 deg reaches it, the largest angle
// whose chief ray still passes (a circular fisheye on a larger sensor).
struct FieldLimit {
  double angleDeg = 0.0;
  double imageHeightMm = 0.0;  // reached by that angle's chief ray
  bool reachedTarget = true;
};
FieldLimit fieldForImageHeight(const LensSystem& lens, double objectDistanceMm, double filmDistanceMm,
                               double imageHeightMm);
// The field angle (deg, >= 0) whose chief ray lands at image height
// `imageHeightMm` (a magnitude) on the film; nullopt when no angle below 89.5
// deg reaches it.
std::optional<double> fieldAngleForImageHeight(const LensSystem& lens, double objectDistanceMm,
                                               double filmDistanceMm, double imageHeightMm);

struct DistortionPoint {
  double fieldAngleDeg = 0.0;
  double realHeightMm = 0.0;      // magnitude of the chief ray's image height
  double paraxialHeightMm = 0.0;  // magnitude of the paraxial image height
  double percent = 0.0;           // 0 on the axis (the limit)
};
// `points` field angles evenly spaced from 0 to the angle whose chief ray
// reaches `maxImageHeightMm` (or the largest traceable one). Angles whose
// chief ray is blocked are left out.
std::vector<DistortionPoint> distortionCurve(const LensSystem& lens, double objectDistanceMm,
                                             double filmDistanceMm, double maxImageHeightMm, int points = 41);

}  // namespace lensrt
