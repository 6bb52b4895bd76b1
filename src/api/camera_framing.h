// The field of view a scene without a camera is framed for: the chosen
// camera's own (docs/cameras-and-lenses.md, "Framing").
#pragma once

#include <functional>

#include "api/camera_spec.h"
#include "scene/camera_selection.h"

namespace lensrt {

// The chosen camera's field at an aspect ratio (width / height), on its
// sensor cropped as the film is: the pinhole's by --focal-length or its
// lens's (at its focus), the thin lens's by its focal length, the thick
// lens's by the paraxial optics at the focus, the full lens's by tracing the
// chief ray to the middle of the shorter edge (a wide or fisheye lens's real
// field). Empty when nothing sets one (a bare pinhole or thin lens keeps the
// default view's 40 degrees) or the lens cannot be read: the camera's build
// then reports the lens, naming its file.
std::function<FramingField(float aspect)> cameraFramingField(const CameraSpec& camera);

}  // namespace lensrt
