// Builds the camera that renders from the scene's camera description and the
// output resolution. One place, so new camera models plug in here.
#pragma once

#include <memory>

#include "camera/camera.h"
#include "core/warnings.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The sensor is 36 mm wide with square pixels (height = 36 mm x height / width).
FilmGeometry filmFor(int width, int height);

// Today: a pinhole with the glTF camera's vertical field of view. Orthographic
// glTF cameras are rendered as perspective ones (with a warning).
std::unique_ptr<Camera> makeCamera(const CameraDesc& desc, const FilmGeometry& film, Warnings& warnings);

}  // namespace lensrt
