// The small JSON each frame of `lensrt render --frames` writes beside its
// image (frame.####.camera.json): when the frame was taken, where the camera
// stood (glTF's and OpenCV's conventions) and the OpenCV intrinsics fitted to
// the lens as it was set for that frame (api/lens_calibration.h), so a
// vision pipeline reads each frame's camera without a renderer.
#pragma once

#include <nlohmann/json.hpp>

#include "api/render_spec.h"
#include "camera/camera.h"
#include "core/warnings.h"

namespace lensrt {

// The frame's camera as rendered (`camera`, made from `spec` at its time):
//  - time_s (when the shutter opens), shutter_s;
//  - world_from_camera: 4 x 4, rows, glTF's camera frame (x right, y up,
//    looking down -z), metres; position_m;
//  - opencv: {R, t}, x_cam = R x_world + t in OpenCV's camera frame (x right,
//    y down, looking down +z), the extrinsics cv2.calibrateCamera recovers;
//  - intrinsics: calibrationJson of the fit (OpenCV's 5-coefficient model,
//    the fisheye's where that one misses by more than a pixel), or null with
//    intrinsics_error saying why (an orthographic camera, a lens no model fits).
nlohmann::json frameCameraJson(const RenderSpec& spec, const Camera& camera, Warnings& warnings);

}  // namespace lensrt
