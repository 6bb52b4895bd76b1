#include "camera/stop_diffraction.h"

#include <cmath>
#include <stdexcept>

namespace lensrt {

StopDiffraction::StopDiffraction(const std::function<double(double, double)>& stop, double pupilRadiusMm)
    : farField_(stop), pupilRadiusMm_(pupilRadiusMm) {
  if (!(pupilRadiusMm > 0.0) || !std::isfinite(pupilRadiusMm))
    throw std::invalid_argument("diffraction needs a pupil of positive radius");
}

std::function<double(double, double)> StopDiffraction::apertureStop(const Aperture& aperture) {
  if (aperture.shape().blades == 0) return {};
  const double r = aperture.circumradius();
  return [aperture, r](double x, double y) { return aperture.contains({x * r, y * r}) ? 1.0 : 0.0; };
}

std::optional<Vec3f> StopDiffraction::bend(const Vec3f& direction, const Vec2f& u, float wavelengthNm) const {
  const StopFarField::Sample f = farField_.sample({double(u.x), double(u.y)});
  // Direction cosines change by lambda / a per cycle per radius (both mm).
  const double k = double(wavelengthNm) * 1e-6 / pupilRadiusMm_;
  const double x = double(direction.x) + k * f.frequency.x, y = double(direction.y) + k * f.frequency.y;
  const double z2 = 1.0 - x * x - y * y;
  if (!(z2 > 0.0)) return std::nullopt;
  // The same side of the lens the ray left on.
  const double z = std::copysign(std::sqrt(z2), double(direction.z));
  return Vec3f{float(x), float(y), float(z)};
}

}  // namespace lensrt
