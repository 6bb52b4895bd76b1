// A camera as `lensrt render` makes it, without a scene: for the projection
// (Lens.project, Lens.unproject) and the calibration, which need the camera's
// geometry and no picture. The focus must be a distance or inf ('auto'
// measures the scene).
#pragma once

#include <memory>

#include "api/camera_options.h"
#include "camera/camera.h"
#include "core/transform.h"
#include "core/warnings.h"

namespace lensrt {

struct StandaloneCamera {
  std::unique_ptr<Camera> camera;
  double focusMetres = 0.0;  // infinity allowed
};

// makeCamera with a width x height raster and the pose. UsageError for a
// raster outside 2x2..65536x65536 or a focus of 'auto'; makeCamera's errors.
StandaloneCamera makeStandaloneCamera(const CameraOptions& options, int width, int height,
                                      const Transform& worldFromCamera, Warnings& warnings);

}  // namespace lensrt
