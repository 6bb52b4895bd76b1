#pragma once

#include <optional>
#include <string>

#include "camera/camera.h"

namespace lensrt {

// glTF's orthographic camera: parallel rays along -Z from the camera's plane,
// the view 2 ymag high (metres) and as wide as the image's aspect ratio makes
// it (2 xmag when the image has glTF's aspect xmag / ymag), so pixels stay
// square. What lies behind the camera's plane is not seen. It records
// radiance, as the pinhole's default film does: with no lens there is no
// irradiance to speak of.
class OrthographicCamera final : public Camera {
 public:
  // Throws std::invalid_argument unless ymag is positive and finite.
  OrthographicCamera(const Transform& worldFromCamera, const FilmGeometry& film, double ymag);

  std::string describe() const override;
  CameraInfo info() const override;
  double halfWidth() const { return halfWidth_; }
  double halfHeight() const { return halfHeight_; }
  ProjectedPoint projectCameraPoint(const Vec3d& point, double wavelengthNm) const override;
  ProjectedRay unprojectRaster(const Vec2d& raster, double wavelengthNm) const override;

 protected:
  std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const override;

 private:
  double halfWidth_, halfHeight_;
};

}  // namespace lensrt
