#include "camera/orthographic_camera.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "camera/film_mapping.h"

namespace lensrt {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

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

// Parallel projection along -Z: x and y scale to the frame.
ProjectedPoint OrthographicCamera::projectCameraPoint(const Vec3d& p, double) const {
  if (!(p.z < 0.0) || !isFinite(p)) return {{kNaN, kNaN}, Visibility::Behind};
  const FilmGeometry& f = film();
  const Vec2d raster{(p.x / halfWidth_ + 1.0) * 0.5 * f.width, (1.0 - p.y / halfHeight_) * 0.5 * f.height};
  return {raster, frameVisibility(f, raster)};
}

ProjectedRay OrthographicCamera::unprojectRaster(const Vec2d& raster, double) const {
  const FilmGeometry& f = film();
  const double ndcX = 2.0 * raster.x / f.width - 1.0, ndcY = 1.0 - 2.0 * raster.y / f.height;
  return {{ndcX * halfWidth_, ndcY * halfHeight_, 0.0}, {0.0, 0.0, -1.0}, frameVisibility(f, raster)};
}

}  // namespace lensrt
