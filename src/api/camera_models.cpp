#include "api/camera_models.h"

namespace lensrt {

const std::vector<CameraModelInfo>& cameraModels() {
  static const std::vector<CameraModelInfo> models{
      {CameraModel::Pinhole, "pinhole", "an ideal pinhole: no depth of field"},
      {CameraModel::Thin, "thin", "an ideal thin lens of the lens's focal length and f-number"},
      {CameraModel::Thick, "thick", "the lens's paraxial model: its cardinal points and pupils"},
      {CameraModel::Lens, "lens", "traced through every element of the lens"},
  };
  return models;
}

const std::string& cameraModelName(CameraModel model) {
  for (const CameraModelInfo& m : cameraModels())
    if (m.model == model) return m.name;
  return cameraModels().front().name;
}

}  // namespace lensrt
