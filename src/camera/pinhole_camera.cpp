#include "camera/pinhole_camera.h"

#include <cmath>
#include <stdexcept>

#include "core/constants.h"

namespace lensrt {

PinholeCamera::PinholeCamera(const Transform& worldFromCamera, const FilmGeometry& film,
                             double yfovRadians)
    : Camera(worldFromCamera, film), yfov_(yfovRadians), tanHalfY_(std::tan(yfovRadians / 2)) {
  if (!(yfovRadians > 0 && yfovRadians < kPi))
    throw std::invalid_argument("pinhole field of view must be between 0 and 180 degrees");
}

std::string PinholeCamera::describe() const {
  return "pinhole yfov=" + std::to_string(yfov_ * 180.0 / kPi) + "deg";
}

std::optional<CameraRay> PinholeCamera::generateCameraSpaceRay(const CameraSample& s) const {
  const FilmGeometry& f = film();
  const double aspect = double(f.width) / f.height;
  // Normalised device coordinates in [-1,1], y up.
  const double ndcX = 2.0 * s.film.x / f.width - 1.0;
  const double ndcY = 1.0 - 2.0 * s.film.y / f.height;
  const Vec3f d{float(ndcX * tanHalfY_ * aspect), float(ndcY * tanHalfY_), -1.0f};
  return CameraRay{Ray{{0, 0, 0}, d}, 1.0f};
}

}  // namespace lensrt
