// --diffraction on: each camera ray bent by the Fraunhofer far field of the
// stop's shape, at the ray's wavelength (docs/design/diffraction.md).
//
// The bend is applied to the ray leaving the camera into the scene, in
// object space, where the stop's image (the entrance pupil) of radius a
// diffracts it: its direction cosines change by (lambda / a) f, f drawn from
// optics/stop_far_field.h's table (cycles per pupil radius) with density
// |T(f)|^2. The light is moved, never lost: the weight stays, so the bend
// conserves flux exactly.
#pragma once

#include <functional>
#include <optional>

#include "camera/aperture.h"
#include "core/vec.h"
#include "optics/stop_far_field.h"

namespace lensrt {

class StopDiffraction {
 public:
  // `stop`: the intensity transmittance over the pupil in units of its
  // radius (x, y in [-1, 1]; the unit disk bounds it); empty: round.
  // `pupilRadiusMm`: the entrance pupil's radius that unit stands for.
  StopDiffraction(const std::function<double(double, double)>& stop, double pupilRadiusMm);

  // The stop of an aperture (a disk or N blades) as a transmittance in
  // units of its circumradius, which is then the pupil radius to pass.
  static std::function<double(double, double)> apertureStop(const Aperture& aperture);

  // `direction` (camera space, unit length, the optical axis along -z) bent
  // by a far-field direction drawn from `u` at `wavelengthNm`; none when the
  // bend would turn it past the lens's plane (not for any table a real lens
  // gives: the table ends 16 cycles per radius out).
  std::optional<Vec3f> bend(const Vec3f& direction, const Vec2f& u, float wavelengthNm) const;

 private:
  StopFarField farField_;
  double pupilRadiusMm_ = 0.0;
};

}  // namespace lensrt
