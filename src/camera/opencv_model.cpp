#include "camera/opencv_model.h"

namespace lensrt {

std::string openCvModelName(OpenCvModel model) {
  switch (model) {
    case OpenCvModel::OpenCv:
      return "opencv";
    case OpenCvModel::OpenCv4:
      return "opencv4";
    case OpenCvModel::FullOpenCv:
      return "full-opencv";
    case OpenCvModel::Fisheye:
      return "fisheye";
  }
  return "";
}

std::optional<OpenCvModel> parseOpenCvModel(const std::string& name) {
  for (const OpenCvModel m :
       {OpenCvModel::OpenCv, OpenCvModel::OpenCv4, OpenCvModel::FullOpenCv, OpenCvModel::Fisheye})
    if (name == openCvModelName(m)) return m;
  return std::nullopt;
}

std::vector<std::string> openCvCoefficientNames(OpenCvModel model) {
  switch (model) {
    case OpenCvModel::OpenCv:
      return {"k1", "k2", "p1", "p2", "k3"};
    case OpenCvModel::OpenCv4:
      return {"k1", "k2", "p1", "p2"};
    case OpenCvModel::FullOpenCv:
      return {"k1", "k2", "p1", "p2", "k3", "k4", "k5", "k6"};
    case OpenCvModel::Fisheye:
      return {"k1", "k2", "k3", "k4"};
  }
  return {};
}

int openCvCoefficientCount(OpenCvModel model) {
  return int(openCvCoefficientNames(model).size());
}

}  // namespace lensrt
