#pragma once

#include "camera/camera.h"

namespace lensrt {

// Ideal perspective projection through a point. Its film records radiance
// directly (weight 1): the normalized exposure of an ideal lens on axis.
class PinholeCamera final : public Camera {
 public:
  // yfovRadians spans the film height; the horizontal field follows from the
  // film's aspect ratio (pixels are square on the sensor).
  PinholeCamera(const Transform& worldFromCamera, const FilmGeometry& film, double yfovRadians);

  std::string describe() const override;
  double yfov() const { return yfov_; }

 protected:
  std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const override;

 private:
  double yfov_;
  double tanHalfY_;
};

}  // namespace lensrt
