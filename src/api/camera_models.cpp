#include "api/camera_models.h"

namespace lensrt {

// Each model's entry, from its own file.
CameraModelInfo pinholeModel();
CameraModelInfo thinLensModel();
CameraModelInfo thickLensModel();
CameraModelInfo fullLensModel();

const std::vector<CameraModelInfo>& cameraModels() {
  static const std::vector<CameraModelInfo> models{pinholeModel(), thinLensModel(), thickLensModel(),
                                                   fullLensModel()};
  return models;
}

const CameraModelInfo& cameraModel(CameraModel model) {
  for (const CameraModelInfo& m : cameraModels())
    if (m.model == model) return m;
  return cameraModels().front();
}

const std::string& cameraModelName(CameraModel model) {
  return cameraModel(model).name;
}

}  // namespace lensrt
