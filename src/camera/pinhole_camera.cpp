#include "camera/pinhole_camera.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "camera/film_mapping.h"
#include "core/constants.h"

namespace lensrt {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

PinholeCamera::PinholeCamera(const Transform& worldFromCamera, const FilmGeometry& film, double yfovRadians,
                             std::string lensName, const LensMovements& movements)
    : Camera(worldFromCamera, film),
      yfov_(yfovRadians),
      tanHalfY_(std::tan(yfovRadians / 2)),
      lensName_(std::move(lensName)),
      movements_(movements) {
  if (!(yfovRadians > 0 && yfovRadians < kPi))
    throw std::invalid_argument("pinhole field of view must be between 0 and 180 degrees");
  checkLensMovements(movements, film, "pinhole");
  if (movements.tilted())
    throw std::invalid_argument("pinhole: a tilt needs a lens's plane of focus (thin, thick or lens)");
  // The film lies at d = 0.5 h / tan(yfov / 2) behind the pinhole.
  shiftTan_ = movements.shiftMm * (2.0 * tanHalfY_ / film.sensorHeightMm);
}

PinholeCamera::PinholeCamera(const Transform& worldFromCamera, const FilmGeometry& film, double yfovRadians,
                             const Exposure& exposure, double fNumber, std::string lensName,
                             const LensMovements& movements)
    : PinholeCamera(worldFromCamera, film, yfovRadians, std::move(lensName), movements) {
  onAxisWeight_ = exposureScale(exposure, fNumber) * idealIrradianceRatio(fNumber);
  exposure_ = exposure;
  fNumber_ = fNumber;
}

std::string PinholeCamera::describe() const {
  // The film is part of the description (the merge/resume identity): parts
  // recorded in radiance and in irradiance must not be joined.
  return "pinhole yfov=" + std::to_string(yfov_ * 180.0 / kPi) +
         "deg film=" + (onAxisWeight_ ? "irradiance" : "radiance") + movements_.describe();
}

CameraInfo PinholeCamera::info() const {
  CameraInfo i;
  i.model = "pinhole";
  i.lens = lensName_;
  i.focalLengthMm = 0.5 * film().sensorHeightMm / tanHalfY_;
  i.exposure = onAxisWeight_ ? lensrt::describe(exposure_) : "none";
  i.film = onAxisWeight_ ? "irradiance" : "radiance";
  i.movements = movements_;
  i.entrancePupilOffsetMm = i.focalLengthMm;  // the pinhole, its focal length from the film
  return i;
}

std::optional<CameraRay> PinholeCamera::generateCameraSpaceRay(const CameraSample& s) const {
  const FilmGeometry& f = film();
  const double aspect = double(f.width) / f.height;
  // Normalised device coordinates in [-1,1], y up.
  const double ndcX = 2.0 * s.film.x / f.width - 1.0;
  const double ndcY = 1.0 - 2.0 * s.film.y / f.height;
  double dx = ndcX * tanHalfY_ * aspect, dy = ndcY * tanHalfY_;
  if (movements_.shifted()) {
    dx += shiftTan_.x;
    dy += shiftTan_.y;
  }
  float weight = 1.0f;
  if (onAxisWeight_) {
    const double cos2 = 1.0 / (1.0 + dx * dx + dy * dy);
    weight = float(*onAxisWeight_ * cos2 * cos2);
  }
  return CameraRay{Ray{{0, 0, 0}, {float(dx), float(dy), -1.0f}}, weight};
}

// Through the pinhole: the tangents of the point's angles, scaled to the frame.
ProjectedPoint PinholeCamera::projectCameraPoint(const Vec3d& p, double) const {
  if (!(p.z < 0.0) || !isFinite(p)) return {{kNaN, kNaN}, Visibility::Behind};
  const FilmGeometry& f = film();
  const double aspect = double(f.width) / f.height;
  // A shift moves the film (tilts are refused): the tangent less the shift's.
  const double ndcX = (p.x / -p.z - shiftTan_.x) / (tanHalfY_ * aspect),
               ndcY = (p.y / -p.z - shiftTan_.y) / tanHalfY_;
  const Vec2d raster{(ndcX + 1.0) * 0.5 * f.width, (1.0 - ndcY) * 0.5 * f.height};
  return {raster, frameVisibility(f, raster)};
}

ProjectedRay PinholeCamera::unprojectRaster(const Vec2d& raster, double) const {
  const FilmGeometry& f = film();
  const double aspect = double(f.width) / f.height;
  const double ndcX = 2.0 * raster.x / f.width - 1.0, ndcY = 1.0 - 2.0 * raster.y / f.height;
  return {{0.0, 0.0, 0.0},
          normalize(Vec3d{ndcX * tanHalfY_ * aspect + shiftTan_.x, ndcY * tanHalfY_ + shiftTan_.y, -1.0}),
          frameVisibility(f, raster)};
}

}  // namespace lensrt
