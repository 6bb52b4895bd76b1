// The camera models, as a list: their names and what each is. `render`'s
// --camera, `compare`'s four renders, the report and Python read it here.
// camera_factory.h makes each.
#pragma once

#include <string>
#include <vector>

#include "api/camera_spec.h"

namespace lensrt {

struct CameraModelInfo {
  CameraModel model;
  std::string name;         // "pinhole", as --camera takes it
  std::string description;  // one line for help and reports
};

// In the order `compare` renders them: the full lens, the reference, last.
const std::vector<CameraModelInfo>& cameraModels();
const std::string& cameraModelName(CameraModel model);

}  // namespace lensrt
