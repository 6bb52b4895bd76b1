#include "app/camera_setup.h"

#include "camera/pinhole_camera.h"

namespace lensrt {

FilmGeometry filmFor(int width, int height) {
  FilmGeometry f;
  f.width = width;
  f.height = height;
  f.sensorWidthMm = 36.0;
  f.sensorHeightMm = 36.0 * double(height) / double(width);
  return f;
}

std::unique_ptr<Camera> makeCamera(const CameraDesc& desc, const FilmGeometry& film, Warnings& warnings) {
  if (desc.orthographic)
    warnings.warn("camera '" + desc.name + "' is orthographic; rendering it as a pinhole with yfov " +
                  std::to_string(desc.yfov) + " rad");
  return std::make_unique<PinholeCamera>(desc.worldFromCamera, film, desc.yfov);
}

}  // namespace lensrt
