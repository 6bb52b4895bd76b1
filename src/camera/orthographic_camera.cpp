#include "camera/orthographic_camera.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lensrt {

OrthographicCamera::OrthographicCamera(const Transform& worldFromCamera, const FilmGeometry& film,
                                       double ymag)
    : Camera(worldFromCamera, film), halfWidth_(ymag * film.width / film.height), halfHeight_(ymag) {
  if (!(ymag > 0 && std::isfinite(ymag)))
    throw std::invalid_argument("orthographic camera: ymag must be positive and finite");
}

std::string OrthographicCamera::describe() const {
  // Part of the render's identity (merge, resume).
  char buf[96];
  std::snprintf(buf, sizeof buf, "orthographic xmag=%.7g ymag=%.7g film=radiance", halfWidth_, halfHeight_);
  return buf;
}

CameraInfo OrthographicCamera::info() const {
  CameraInfo i;
  i.model = "orthographic";
  i.exposure = "none";
  i.film = "radiance";
  return i;
}

std::optional<CameraRay> OrthographicCamera::generateCameraSpaceRay(const CameraSample& s) const {
  const FilmGeometry& f = film();
  // Normalised device coordinates in [-1,1], y up, as the pinhole's.
  const double ndcX = 2.0 * s.film.x / f.width - 1.0;
  const double ndcY = 1.0 - 2.0 * s.film.y / f.height;
  return CameraRay{Ray{{float(ndcX * halfWidth_), float(ndcY * halfHeight_), 0.0f}, {0.0f, 0.0f, -1.0f}},
                   1.0f};
}

}  // namespace lensrt
