// OpenCV's camera models, as its calib3d module and COLMAP define them:
// where a normalised point (x, y) = (X / Z, Y / Z) of OpenCV's camera frame
// (x right, y down, z forward) lands in OpenCV's pixels (the top-left
// pixel's centre at (0, 0)). Templated on the number type, so the fit
// (api/lens_calibration.h) takes its exact derivatives by automatic
// differentiation.
//
// Design notes: docs/design/opencv-model.md.
#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace lensrt {

enum class OpenCvModel { OpenCv, OpenCv4, FullOpenCv, Fisheye };

// "opencv", "opencv4", "full-opencv", "fisheye".
std::string openCvModelName(OpenCvModel model);
std::optional<OpenCvModel> parseOpenCvModel(const std::string& name);

// The distortion coefficients in OpenCV's order: opencv k1 k2 p1 p2 k3;
// opencv4 k1 k2 p1 p2; full-opencv k1 k2 p1 p2 k3 k4 k5 k6; fisheye k1 k2 k3 k4.
int openCvCoefficientCount(OpenCvModel model);
// Their names in that order ("k1", "k2", "p1", ...).
std::vector<std::string> openCvCoefficientNames(OpenCvModel model);

// The intrinsics (fx, fy, cx, cy) and the coefficients, in one array.
struct OpenCvCamera {
  OpenCvModel model = OpenCvModel::OpenCv;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  std::vector<double> coefficients;  // openCvCoefficientCount(model) of them
};

// u, v of the normalised point (x, y); `p` holds fx, fy, cx, cy and the
// model's coefficients in OpenCV's order.
template <class T>
void openCvProject(OpenCvModel model, const T* p, const T& x, const T& y, T& u, T& v) {
  using std::atan2;  // atan(r) as atan2(r, 1): Eigen's automatic differentiation has no atan
  using std::sqrt;
  const T& fx = p[0];
  const T& fy = p[1];
  const T& cx = p[2];
  const T& cy = p[3];
  const T* k = p + 4;
  if (model == OpenCvModel::Fisheye) {
    const T r2 = x * x + y * y;
    // theta_d / r tends to 1 on the axis (and the derivative stays finite).
    T scale = T(1.0);
    if (r2 > T(1e-24)) {
      const T r = sqrt(r2);
      const T theta = atan2(r, T(1.0));
      const T t2 = theta * theta;
      scale = theta * (T(1.0) + t2 * (k[0] + t2 * (k[1] + t2 * (k[2] + t2 * k[3])))) / r;
    }
    u = fx * (scale * x) + cx;
    v = fy * (scale * y) + cy;
    return;
  }
  const T r2 = x * x + y * y;
  const T& p1 = k[2];
  const T& p2 = k[3];
  const T k3 = model == OpenCvModel::OpenCv4 ? T(0.0) : k[4];
  T radial = T(1.0) + r2 * (k[0] + r2 * (k[1] + r2 * k3));
  if (model == OpenCvModel::FullOpenCv) radial = radial / (T(1.0) + r2 * (k[5] + r2 * (k[6] + r2 * k[7])));
  const T xd = x * radial + T(2.0) * p1 * x * y + p2 * (r2 + T(2.0) * x * x);
  const T yd = y * radial + p1 * (r2 + T(2.0) * y * y) + T(2.0) * p2 * x * y;
  u = fx * xd + cx;
  v = fy * yd + cy;
}

// The same for a fitted camera.
inline void openCvProject(const OpenCvCamera& c, double x, double y, double& u, double& v) {
  std::vector<double> p{c.fx, c.fy, c.cx, c.cy};
  p.insert(p.end(), c.coefficients.begin(), c.coefficients.end());
  openCvProject(c.model, p.data(), x, y, u, v);
}

}  // namespace lensrt
