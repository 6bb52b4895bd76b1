#include "api/frame_camera.h"

#include <array>
#include <exception>
#include <limits>
#include <string>

#include "api/lens_calibration.h"

namespace lensrt {
namespace {

// The camera spec the frame's camera was made from, with what the render
// resolved put in: the focus (auto or keyframed) and the f-number at the
// frame's time, and the focal length a glTF camera's field gave the
// pinhole or the thin lens.
CameraSpec resolvedSpec(const CameraSpec& given, const CameraInfo& info) {
  CameraSpec c = given;
  c.focusKeys.clear();
  c.fNumberKeys.clear();
  c.focusPixel.reset();
  // The pinhole has no focus; its projection is the same at any distance.
  c.focusMetres = info.focusMetres > 0 ? info.focusMetres : std::numeric_limits<double>::infinity();
  if (info.fNumber > 0) c.fNumber = info.fNumber;
  if (!c.focalLengthMm && c.lens.empty() && info.focalLengthMm > 0) c.focalLengthMm = info.focalLengthMm;
  return c;
}

nlohmann::json intrinsics(const RenderSpec& spec, const Camera& camera, nlohmann::json& out) {
  CalibrationRequest request;
  request.camera = resolvedSpec(spec.camera, camera.info());
  request.width = camera.film().width;
  request.height = camera.film().height;
  std::string failure;
  // The fisheye model only where OpenCV's usual one cannot follow the lens.
  for (const OpenCvModel model : {OpenCvModel::OpenCv, OpenCvModel::Fisheye}) {
    request.model = model;
    try {
      Warnings quiet;
      return calibrationJson(calibrateLens(request, quiet));
    } catch (const std::exception& e) {  // UsageError, InputError: say why in the file
      if (failure.empty()) failure = e.what();
    }
  }
  out["intrinsics_error"] = failure;
  return nullptr;
}

}  // namespace

nlohmann::json frameCameraJson(const RenderSpec& spec, const Camera& camera, Warnings& warnings) {
  nlohmann::json j;
  j["time_s"] = spec.time.atSeconds();
  j["shutter_s"] = spec.shutter.shutterSeconds();
  const Transform::Matrix& w = camera.worldFromCamera().matrix();
  j["world_from_camera"] = nlohmann::json::array();
  for (const auto& row : w) j["world_from_camera"].push_back(row);
  j["position_m"] = {w[0][3], w[1][3], w[2][3]};
  // OpenCV's camera frame is glTF's with y and z negated: R = diag(1, -1, -1)
  // times the rotation of camera-from-world, t likewise.
  const Transform::Matrix c = camera.worldFromCamera().inverse().matrix();
  std::array<std::array<double, 3>, 3> r{};
  std::array<double, 3> t{};
  for (int row = 0; row < 3; ++row) {
    const double sign = row == 0 ? 1.0 : -1.0;
    for (int col = 0; col < 3; ++col) r[row][col] = sign * c[row][col];
    t[row] = sign * c[row][3];
  }
  j["opencv"] = {{"R", r}, {"t", t}};
  j["intrinsics"] = intrinsics(spec, camera, j);
  if (j["intrinsics"].is_null())
    warnings.warn("no OpenCV intrinsics for the frame's camera JSON: " +
                  j["intrinsics_error"].get<std::string>());
  return j;
}

}  // namespace lensrt
