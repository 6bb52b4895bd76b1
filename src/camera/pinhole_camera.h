#pragma once

#include <optional>

#include "camera/camera.h"
#include "camera/exposure.h"

namespace lensrt {

// Ideal perspective projection through a point at the camera origin.
//
// Two films: the constructor without an exposure records radiance (weight 1:
// the mean radiance along the rays through each pixel, the convention of
// pbrt's perspective camera, Cycles and Mitsuba; `lensrt render`'s default);
// given an exposure, the pinhole records the irradiance of an ideal f/N lens
// shrunk to a point, pi cos^4(theta) / (4 N^2) times the exposure scale (so
// cos^4(theta) when normalized), like the other models.
//
// Movements: the shift alone (lens_movements.h): the frame slides across the
// image plane at the focal distance the field of view implies,
// 0.5 h / tan(yfov / 2). A pinhole has no plane of focus to tilt, so a tilt
// throws std::invalid_argument.
class PinholeCamera final : public Camera {
 public:
  // yfovRadians spans the film height; the horizontal field follows from the
  // film's aspect ratio (pixels are square on the sensor).
  PinholeCamera(const Transform& worldFromCamera, const FilmGeometry& film, double yfovRadians,
                std::string lensName = {}, const LensMovements& movements = {});
  // fNumber only sets the physical exposure (a pinhole has no aperture to speak of).
  PinholeCamera(const Transform& worldFromCamera, const FilmGeometry& film, double yfovRadians,
                const Exposure& exposure, double fNumber, std::string lensName = {},
                const LensMovements& movements = {});

  std::string describe() const override;
  CameraInfo info() const override;
  double yfov() const { return yfov_; }
  const LensMovements& movements() const { return movements_; }
  ProjectedPoint projectCameraPoint(const Vec3d& point, double wavelengthNm) const override;
  ProjectedRay unprojectRaster(const Vec2d& raster, double wavelengthNm) const override;

 protected:
  std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const override;

 private:
  double yfov_;
  double tanHalfY_;
  std::optional<double> onAxisWeight_;  // empty: radiance camera
  Exposure exposure_;
  double fNumber_ = 0.0;
  std::string lensName_;
  LensMovements movements_;
  Vec2d shiftTan_;  // the shift over the focal distance: added to the ray's x, y at z = -1
};

}  // namespace lensrt
