// `lensrt lens calibrate LENS --res WxH --focus M|inf [--sensor WxH|NAME]
//  [--fstop N] [--camera lens|thick|thin|pinhole] [--model opencv|opencv4|
//  full-opencv|fisheye] [--wavelength NM] [--max-residual PX] [--json]
//  [--opencv FILE.yml] [--colmap FILE.txt] [--stmap-undistort FILE.exr]
//  [--stmap-distort FILE.exr]`: OpenCV's camera model fitted to lensrt's
//  projection (api/lens_calibration.h).
#include <fmt/core.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "api/camera_models.h"
#include "api/lens_calibration.h"
#include "api/lens_view.h"
#include "api/option_parsers.h"
#include "api/output_file.h"
#include "api/render_options.h"
#include "api/text_file.h"
#include "app/lens_subcommands.h"
#include "app/option_checks.h"

namespace lensrt {
namespace {

struct CalibrateOptions {
  std::string lens;
  std::string camera = "lens";
  std::string sensor = "36x24";
  std::string res;
  std::string focus;
  std::optional<double> fNumber;
  std::string model = "opencv";
  double wavelengthNm = 587.5618;
  double maxResidualPx = 1.0;
  bool json = false;
  std::string opencv, colmap, stmapUndistort, stmapDistort;
};

void checkExrOutput(const std::string& file, const char* flag) {
  if (file.empty()) return;
  if (std::filesystem::path(file).extension() != ".exr")
    throw UsageError(flag, "an ST map is an OpenEXR file (.exr), got '" + file + "'");
  noteCreatedFolder(checkOutputFile(file), false);
}

void checkTextOutput(const std::string& file) {
  if (file.empty()) return;
  noteCreatedFolder(createFolderFor(file), false);
  checkOutputDirectory(file);
}

int runCalibrate(const CalibrateOptions& o) {
  CalibrationRequest request;
  for (const CameraModelInfo& m : cameraModels())
    if (m.name == o.camera) request.camera.model = m.model;
  request.camera.lens = o.lens;
  request.camera.lensDir = LENSRT_LENS_DIR;
  request.camera.sensorMm = parseSensor(o.sensor);
  request.camera.focusMetres = parseFocusDistance(o.focus);
  request.camera.fNumber = o.fNumber;
  const Resolution res = parseResolution(o.res);
  if (res.height == 0) throw UsageError("--res", "expected WIDTHxHEIGHT in pixels, e.g. 640x360");
  request.width = res.width;
  request.height = res.height;
  request.model = *parseOpenCvModel(o.model);
  request.wavelengthNm = o.wavelengthNm;
  request.maxResidualPx = o.maxResidualPx;
  // Every output checked before the fit, so a mistake costs no work.
  checkTextOutput(o.opencv);
  checkTextOutput(o.colmap);
  checkExrOutput(o.stmapUndistort, "--stmap-undistort");
  checkExrOutput(o.stmapDistort, "--stmap-distort");

  Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
  const Calibration c = calibrateLens(request, warnings);
  if (!o.opencv.empty()) writeTextFileAtomically(o.opencv, openCvYaml(c));
  if (!o.colmap.empty()) writeTextFileAtomically(o.colmap, colmapCamerasTxt(c));
  for (const auto& [file, undistort] : {std::pair{o.stmapUndistort, true}, std::pair{o.stmapDistort, false}})
    if (!file.empty())
      writeOutputImage(file, stMap(c, undistort, warnings),
                       {{"lensrt:stmap", undistort ? "undistort" : "distort"}});
  if (o.json) {
    std::cout << calibrationJson(c).dump(2) << "\n";
  } else {
    const OpenCvCamera& m = c.camera;
    fmt::print("{} ({}), {}x{} px on {:g} x {:g} mm, focused at {}: the {} model\n",
               c.lensName.empty() ? o.lens : c.lensName, o.camera, c.request.width, c.request.height,
               c.sensorWidthMm, c.sensorHeightMm,
               std::isinf(c.focusMetres) ? std::string("infinity") : fmt::format("{:g} m", c.focusMetres),
               openCvModelName(m.model));
    fmt::print(
        "  fx {:.6f}  fy {:.6f}  cx {:.6f}  cy {:.6f}  (OpenCV pixels: the top-left pixel's centre is 0, "
        "0)\n",
        m.fx, m.fy, m.cx, m.cy);
    const std::vector<std::string> names = openCvCoefficientNames(m.model);
    std::string coefficients;
    for (std::size_t i = 0; i < names.size(); ++i)
      coefficients += fmt::format("{}{} {:.9g}", i ? "  " : "", names[i], m.coefficients[i]);
    fmt::print("  {}\n", coefficients);
    fmt::print("  residual over the frame: RMS {:.4f} px, max {:.4f} px ({} points{})\n", c.rmsPx, c.maxPx,
               c.points, c.blocked ? fmt::format(", {} blocked by the lens and left out", c.blocked) : "");
    fmt::print("  COLMAP: {}\n", colmapLine(c));
  }
  for (const std::string& file : {o.opencv, o.colmap, o.stmapUndistort, o.stmapDistort})
    if (!file.empty()) fmt::print(stderr, "lensrt: wrote {}\n", file);
  return 0;
}

}  // namespace

CommandAction addLensCalibrateCommand(CLI::App& lensApp, const CommandContext&) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = lensApp.add_subcommand(
      "calibrate",
      "Fit OpenCV's camera model (or the fisheye one) to lensrt's projection through the lens: intrinsics, "
      "distortion, the residual; OpenCV YAML, COLMAP cameras.txt, JSON and ST maps");
  cmd->add_option("lens", options->lens,
                  "Lens file (.lens, .json, .dat, .zmx) or library name, e.g. dgauss-50mm")
      ->required();
  cmd->add_option("--res", options->res, "The render's resolution WIDTHxHEIGHT in pixels")->required();
  cmd->add_option(
         "--focus", options->focus,
         "Focus distance in metres from the entrance pupil, or 'inf': the model is fitted on that plane")
      ->required();
  cmd->add_option("--sensor", options->sensor,
                  "Sensor WIDTHxHEIGHT in mm or a name (full-frame, aps-c, mft, 1in), cropped to the image's "
                  "aspect as the render does")
      ->capture_default_str();
  cmd->add_option("--fstop", options->fNumber,
                  "The render's f-number (the focus depends on it only through the stop)")
      ->check(aNumber("an f-number"));
  cmd->add_option("--camera", options->camera, "The camera model whose projection is fitted")
      ->capture_default_str()
      ->check(CLI::IsMember({"lens", "thick", "thin", "pinhole"}));
  cmd->add_option("--model", options->model,
                  "opencv (k1 k2 p1 p2 k3), opencv4 (k1 k2 p1 p2: COLMAP's OPENCV), full-opencv (k1..k6, p1, "
                  "p2) or fisheye (Kannala-Brandt k1..k4, cv::fisheye)")
      ->capture_default_str()
      ->check(CLI::IsMember({"opencv", "opencv4", "full-opencv", "fisheye"}));
  cmd->add_option("--wavelength", options->wavelengthNm,
                  "The wavelength in nm (default the d line, 587.5618)")
      ->check(aNumber("nm"));
  cmd->add_option("--max-residual", options->maxResidualPx,
                  "Refuse a fit whose largest residual over the frame exceeds this many pixels")
      ->capture_default_str()
      ->check(aNumber("pixels"));
  cmd->add_flag("--json", options->json, "Print JSON (the dict lensrt.Lens.calibrate returns)");
  cmd->add_option("--opencv", options->opencv, "Write OpenCV FileStorage YAML (cv::FileStorage reads it)");
  cmd->add_option("--colmap", options->colmap, "Write COLMAP's cameras.txt (one camera)");
  cmd->add_option(
      "--stmap-undistort", options->stmapUndistort,
      "Write the ST map (Nuke's convention, .exr) that turns lensrt's image into the ideal pinhole "
      "image of the fitted fx, fy, cx, cy");
  cmd->add_option("--stmap-distort", options->stmapDistort,
                  "Write the ST map (.exr) that turns that ideal pinhole image into lensrt's");
  return [options] { return runCalibrate(*options); };
}

}  // namespace lensrt
