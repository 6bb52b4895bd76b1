// A camera as `lensrt render` makes it, without a scene: for the projection
// (Lens.project, Lens.unproject) and the calibration, which need the camera's
// geometry and no picture. The focus must be a distance or inf (auto focus
// measures the scene), and neither it nor the f-number keyframed.
#pragma once

#include <memory>

#include "api/camera_spec.h"
#include "camera/camera.h"
#include "core/transform.h"
#include "core/warnings.h"

namespace lensrt {

struct StandaloneCamera {
  std::unique_ptr<Camera> camera;
  double focusMetres = 0.0;  // infinity allowed
};

// makeCamera (api/camera_factory.h) with a width x height raster and the
// pose, the default shutter and no flare. UsageError for a raster outside
// 2x2..65536x65536, auto focus or keyframes; makeCamera's errors.
StandaloneCamera makeStandaloneCamera(const CameraSpec& spec, int width, int height,
                                      const Transform& worldFromCamera, Warnings& warnings);

}  // namespace lensrt
