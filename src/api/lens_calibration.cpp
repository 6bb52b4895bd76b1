#include "api/lens_calibration.h"

#include <fmt/core.h>
#include <tbb/parallel_for.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <unsupported/Eigen/AutoDiff>
#include <unsupported/Eigen/NonLinearOptimization>
#include <vector>

#include "api/standalone_camera.h"
#include "camera/film_mapping.h"
#include "core/constants.h"
#include "core/error.h"

namespace lensrt {
namespace {

constexpr int kGridColumns = 64;  // intervals across the frame
// Where an ST map for a lens focused at infinity puts the points it projects.
constexpr double kFarMetres = 1000.0;

// A grid point: its normalised point in OpenCV's camera frame and its
// position in OpenCV's pixels.
struct Sample {
  double x = 0.0, y = 0.0;
  double u = 0.0, v = 0.0;
};

StandaloneCamera buildCamera(const CalibrationRequest& r, Warnings& warnings) {
  if (!(r.wavelengthNm >= 360.0 && r.wavelengthNm <= 830.0))
    throw UsageError("--wavelength", fmt::format("expected 360 to 830 nm, got {:g}", r.wavelengthNm));
  if (!(r.maxResidualPx > 0.0))
    throw UsageError("--max-residual", fmt::format("expected pixels > 0, got {:g}", r.maxResidualPx));
  return makeStandaloneCamera(r.camera, r.width, r.height, Transform(), warnings);
}

// The normalised point (X / Z, Y / Z) of OpenCV's frame (X = x, Y = -y,
// Z = -z of camera space) where a chief ray meets the focus plane, or its
// direction for a focus at infinity.
std::optional<Vec2d> normalisedPoint(const ProjectedRay& r, double focusMetres) {
  if (!(r.direction.z < 0.0)) return std::nullopt;
  if (std::isinf(focusMetres)) return Vec2d{r.direction.x / -r.direction.z, r.direction.y / r.direction.z};
  const Vec3d p = r.origin + r.direction * ((-focusMetres - r.origin.z) / r.direction.z);
  return Vec2d{p.x / -p.z, p.y / p.z};
}

// The camera-space point that an OpenCV normalised point stands for, on the
// focus plane (at kFarMetres for a focus at infinity).
Vec3d cameraPoint(const Vec2d& normalised, double focusMetres) {
  const double z = std::isinf(focusMetres) ? kFarMetres : focusMetres;
  return {normalised.x * z, -normalised.y * z, -z};
}

// The residuals (model - grid, in pixels) and, for Levenberg-Marquardt,
// their exact derivatives by automatic differentiation over the N
// parameters (fx, fy, cx, cy and the coefficients).
template <int N>
struct FitFunctor {
  using Scalar = double;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;

  OpenCvModel model;
  const std::vector<Sample>* samples;

  int inputs() const { return N; }
  int values() const { return int(2 * samples->size()); }
  int operator()(const Eigen::VectorXd& p, Eigen::VectorXd& f) const {
    for (std::size_t i = 0; i < samples->size(); ++i) {
      const Sample& s = (*samples)[i];
      double u = 0.0, v = 0.0;
      openCvProject(model, p.data(), s.x, s.y, u, v);
      f[Eigen::Index(2 * i)] = u - s.u;
      f[Eigen::Index(2 * i + 1)] = v - s.v;
    }
    return 0;
  }
  int df(const Eigen::VectorXd& p, Eigen::MatrixXd& jacobian) const {
    using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    std::array<Dual, N> q;
    for (int k = 0; k < N; ++k) q[std::size_t(k)] = Dual(p[k], N, k);
    for (std::size_t i = 0; i < samples->size(); ++i) {
      const Sample& s = (*samples)[i];
      Dual u, v;
      openCvProject(model, q.data(), Dual(s.x), Dual(s.y), u, v);
      jacobian.row(Eigen::Index(2 * i)) = u.derivatives().transpose();
      jacobian.row(Eigen::Index(2 * i + 1)) = v.derivatives().transpose();
    }
    return 0;
  }
};

template <int N>
void minimise(OpenCvModel model, const std::vector<Sample>& samples, Eigen::VectorXd& p) {
  FitFunctor<N> functor{model, &samples};
  Eigen::LevenbergMarquardt<FitFunctor<N>> lm(functor);
  lm.parameters.maxfev = 4000;
  lm.parameters.ftol = 1e-15;
  lm.parameters.xtol = 1e-15;
  lm.minimize(p);
}

// fx, cx (or fy, cy) by linear least squares on u = f a + c, with no
// distortion: the start of the fit.
std::pair<double, double> linearFit(const std::vector<double>& a, const std::vector<double>& u) {
  double ma = 0.0, mu = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i], mu += u[i];
  ma /= double(a.size()), mu /= double(a.size());
  double saa = 0.0, sau = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    saa += (a[i] - ma) * (a[i] - ma), sau += (a[i] - ma) * (u[i] - mu);
  const double f = sau / saa;
  return {f, mu - f * ma};
}

}  // namespace

Calibration fitLens(const CalibrationRequest& request, Warnings& warnings) {
  const StandaloneCamera built = buildCamera(request, warnings);
  const Camera& camera = *built.camera;
  Calibration c;
  c.request = request;
  c.focusMetres = built.focusMetres;
  c.cameraDescription = camera.describe();
  c.lensName = camera.info().lens;
  c.sensorWidthMm = camera.film().sensorWidthMm;
  c.sensorHeightMm = camera.film().sensorHeightMm;
  c.camera.model = request.model;

  // The grid, corner to corner.
  const int columns = kGridColumns;
  const int rows = std::max(2, int(std::lround(double(columns) * request.height / request.width)));
  std::vector<Sample> samples;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) {
      const Vec2d raster{double(request.width) * i / columns, double(request.height) * j / rows};
      const ProjectedRay ray = camera.unprojectRaster(raster, request.wavelengthNm);
      const std::optional<Vec2d> n = normalisedPoint(ray, built.focusMetres);
      if (ray.visibility == Visibility::Blocked || !n || !isFinite(Vec3d{n->x, n->y, 0.0})) {
        ++c.blocked;
        continue;
      }
      samples.push_back({n->x, n->y, raster.x - 0.5, raster.y - 0.5});
    }
  const int parameters = 4 + openCvCoefficientCount(request.model);
  c.points = int(samples.size());
  if (c.points < 4 * parameters)
    throw InputError(
        request.camera.lens,
        fmt::format("only {} of the {} grid points over the frame have a chief ray: nothing to fit", c.points,
                    (columns + 1) * (rows + 1)));

  // Start: the pinhole (or equidistant fisheye) by linear least squares.
  std::vector<double> ax, ay, u, v;
  for (const Sample& s : samples) {
    double scale = 1.0;
    if (request.model == OpenCvModel::Fisheye) {
      const double r = std::hypot(s.x, s.y);
      scale = r > 1e-12 ? std::atan(r) / r : 1.0;
    }
    ax.push_back(scale * s.x), ay.push_back(scale * s.y), u.push_back(s.u), v.push_back(s.v);
  }
  const auto [fx, cx] = linearFit(ax, u);
  const auto [fy, cy] = linearFit(ay, v);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(parameters);
  p[0] = fx, p[1] = fy, p[2] = cx, p[3] = cy;
  switch (parameters) {
    case 8:
      minimise<8>(request.model, samples, p);
      break;
    case 9:
      minimise<9>(request.model, samples, p);
      break;
    case 12:
      minimise<12>(request.model, samples, p);
      break;
    default:
      throw std::logic_error("fitLens: no fit for " + std::to_string(parameters) + " parameters");
  }
  c.camera.fx = p[0], c.camera.fy = p[1], c.camera.cx = p[2], c.camera.cy = p[3];
  c.camera.coefficients.assign(p.data() + 4, p.data() + parameters);

  double sum = 0.0;
  for (const Sample& s : samples) {
    double mu = 0.0, mv = 0.0;
    openCvProject(c.camera, s.x, s.y, mu, mv);
    const double e = std::hypot(mu - s.u, mv - s.v);
    sum += e * e;
    c.maxPx = std::max(c.maxPx, e);
  }
  c.rmsPx = std::sqrt(sum / double(samples.size()));
  return c;
}

Calibration calibrateLens(const CalibrationRequest& request, Warnings& warnings) {
  Calibration c = fitLens(request, warnings);
  if (!(c.maxPx <= request.maxResidualPx))
    throw InputError(
        request.camera.lens,
        fmt::format(
            "the {} model misses lensrt's projection by up to {:.3g} px (RMS {:.3g} px) over the {}x{} "
            "frame, more than {:g} px: not written{}",
            openCvModelName(request.model), c.maxPx, c.rmsPx, request.width, request.height,
            request.maxResidualPx,
            request.model == OpenCvModel::FullOpenCv || request.model == OpenCvModel::Fisheye
                ? std::string(" (--max-residual PX accepts it)")
                : std::string("; try --model full-opencv or fisheye (--max-residual PX accepts it)")));
  return c;
}

namespace {

std::string colmapModelName(const Calibration& c) {
  switch (c.camera.model) {
    case OpenCvModel::OpenCv4:
      return "OPENCV";
    case OpenCvModel::OpenCv:
    case OpenCvModel::FullOpenCv:
      return "FULL_OPENCV";
    case OpenCvModel::Fisheye:
      return "OPENCV_FISHEYE";
  }
  return "";
}

std::string number(double v) {
  return fmt::format("{:.17g}", v);
}

}  // namespace

std::string colmapLine(const Calibration& c) {
  const OpenCvCamera& m = c.camera;
  // COLMAP's image coordinates put the top-left pixel's centre at (0.5, 0.5).
  std::string line =
      fmt::format("1 {} {} {} {} {} {} {}", colmapModelName(c), c.request.width, c.request.height,
                  number(m.fx), number(m.fy), number(m.cx + 0.5), number(m.cy + 0.5));
  std::vector<double> k = m.coefficients;
  if (m.model == OpenCvModel::OpenCv) k.resize(8, 0.0);  // FULL_OPENCV with k4 = k5 = k6 = 0
  for (const double v : k) line.append(" ").append(number(v));
  return line;
}

std::string colmapCamerasTxt(const Calibration& c) {
  return "# Camera list with one line of data per camera:\n"
         "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
         "# Number of cameras: 1\n" +
         colmapLine(c) + "\n";
}

std::string openCvYaml(const Calibration& c) {
  const OpenCvCamera& m = c.camera;
  const auto data = [](const std::vector<double>& values) {
    std::string s;
    for (const double v : values) s += (s.empty() ? "" : ", ") + number(v);
    return s;
  };
  return fmt::format(
      "%YAML:1.0\n---\n"
      "image_width: {}\nimage_height: {}\n"
      "model: \"{}\"\n"
      "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ {} ]\n"
      "distortion_coefficients: !!opencv-matrix\n   rows: 1\n   cols: {}\n   dt: d\n   data: [ {} ]\n"
      "rms_residual_px: {}\nmax_residual_px: {}\n",
      c.request.width, c.request.height, openCvModelName(m.model),
      data({m.fx, 0.0, m.cx, 0.0, m.fy, m.cy, 0.0, 0.0, 1.0}), m.coefficients.size(), data(m.coefficients),
      number(c.rmsPx), number(c.maxPx));
}

nlohmann::json calibrationJson(const Calibration& c) {
  const OpenCvCamera& m = c.camera;
  nlohmann::json j;
  j["lens"] = c.lensName;
  j["camera"] = c.cameraDescription;
  j["model"] = openCvModelName(m.model);
  j["width"] = c.request.width;
  j["height"] = c.request.height;
  j["sensor_mm"] = {c.sensorWidthMm, c.sensorHeightMm};
  j["focus_m"] = std::isinf(c.focusMetres) ? nlohmann::json(nullptr) : nlohmann::json(c.focusMetres);
  j["wavelength_nm"] = c.request.wavelengthNm;
  j["fx"] = m.fx;
  j["fy"] = m.fy;
  j["cx"] = m.cx;
  j["cy"] = m.cy;
  const std::vector<std::string> names = openCvCoefficientNames(m.model);
  for (std::size_t i = 0; i < names.size(); ++i) j[names[i]] = m.coefficients[i];
  j["camera_matrix"] = {{m.fx, 0.0, m.cx}, {0.0, m.fy, m.cy}, {0.0, 0.0, 1.0}};
  j["dist_coeffs"] = m.coefficients;
  j["residual_px"] = {{"rms", c.rmsPx}, {"max", c.maxPx}, {"points", c.points}, {"blocked", c.blocked}};
  j["colmap"] = colmapLine(c);
  return j;
}

Image stMap(const Calibration& c, bool undistort, Warnings& warnings) {
  const StandaloneCamera built = buildCamera(c.request, warnings);
  const Camera& camera = *built.camera;
  const OpenCvCamera& m = c.camera;
  const int w = c.request.width, h = c.request.height;
  const double wavelength = c.request.wavelengthNm;
  Image map(w, h, {"R", "G", "B", "A"});
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      // The source position (raster) this pixel reads, if any.
      std::optional<Vec2d> source;
      if (undistort) {
        // This pixel of the ideal image (OpenCV pixel (x, y)) sees the
        // normalised point K^-1 (x, y); lensrt images it at...
        const Vec2d n{(x - m.cx) / m.fx, (y - m.cy) / m.fy};
        const ProjectedPoint p = camera.projectCameraPoint(cameraPoint(n, built.focusMetres), wavelength);
        if (p.visibility == Visibility::Visible || p.visibility == Visibility::OutsideFrame)
          source = p.raster;
      } else {
        // This pixel of lensrt's image sees its chief ray; the ideal image
        // has that ray at K n.
        const ProjectedRay r = camera.unprojectRaster({x + 0.5, y + 0.5}, wavelength);
        const std::optional<Vec2d> n = normalisedPoint(r, built.focusMetres);
        if (r.visibility != Visibility::Blocked && n)
          source = Vec2d{m.fx * n->x + m.cx + 0.5, m.fy * n->y + m.cy + 0.5};
      }
      if (!source) continue;
      map.at(x, y, 0) = float(source->x / w);
      map.at(x, y, 1) = float(1.0 - source->y / h);
      map.at(x, y, 3) = 1.0f;
    }
  });
  return map;
}

}  // namespace lensrt
