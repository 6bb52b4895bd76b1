// `lensrt lens calibrate` and `lensrt.Lens.calibrate`: OpenCV's camera model
// (camera/opencv_model.h) fitted to lensrt's exact projection (camera/
// projection.h), so a vision pipeline reads the lens a render was made with.
//
// Design notes: docs/design/lens-calibration.md.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "api/camera_spec.h"
#include "camera/opencv_model.h"
#include "core/warnings.h"
#include "image/image.h"

namespace lensrt {

struct CalibrationRequest {
  // The camera as a render makes it (api/camera_spec.h): model, lens, the
  // f-number, the focus (metres or infinity: not auto), the sensor;
  // dispersion as the render's default (on).
  CameraSpec camera;
  int width = 0, height = 0;  // raster, pixels
  OpenCvModel model = OpenCvModel::OpenCv;
  double wavelengthNm = 587.5618;  // the d line
  double maxResidualPx = 1.0;      // calibrateLens refuses a fit that misses by more
};

struct Calibration {
  CalibrationRequest request;
  OpenCvCamera camera;
  double rmsPx = 0.0, maxPx = 0.0;  // residuals over the grid
  int points = 0;                   // grid points with a chief ray
  int blocked = 0;                  // grid points the lens blocks (left out)
  double focusMetres = 0.0;         // the plane the points lie on (infinity allowed)
  std::string lensName;
  std::string cameraDescription;                     // the camera's describe()
  double sensorWidthMm = 0.0, sensorHeightMm = 0.0;  // the film, cropped to the raster's aspect
};

// Builds the camera (makeCamera: UsageError, InputError naming the lens),
// fits the model. InputError(lens, reason) when the fit is not good: its
// largest residual over request.maxResidualPx, or too few chief rays.
Calibration calibrateLens(const CalibrationRequest& request, Warnings& warnings);
// The same fit, never refused (tests).
Calibration fitLens(const CalibrationRequest& request, Warnings& warnings);

// JSON: lens, camera, model, width, height, sensor_mm, focus_m (null at
// infinity), wavelength_nm, fx, fy, cx, cy (OpenCV's pixels), the
// coefficients by name, camera_matrix (3 x 3), dist_coeffs (OpenCV's
// order), residual_px {rms, max, points, blocked}, colmap (the cameras.txt line).
nlohmann::json calibrationJson(const Calibration& c);
// OpenCV's FileStorage YAML (cv::FileStorage reads it): image_width,
// image_height, camera_matrix, distortion_coefficients (1 x N), model.
std::string openCvYaml(const Calibration& c);
// COLMAP's cameras.txt: its header and one line "1 MODEL W H fx fy cx cy
// ...", MODEL OPENCV (k3 = 0 only: COLMAP's OPENCV has no k3), FULL_OPENCV
// (also the 5-coefficient fit with k3, k4 = k5 = k6 = 0: the same model) or
// OPENCV_FISHEYE; COLMAP's pixel centres are at +0.5, so its cx, cy are
// OpenCV's + 0.5.
std::string colmapLine(const Calibration& c);
std::string colmapCamerasTxt(const Calibration& c);

// ST maps (Nuke's STMap convention): an image of the frame's size whose red
// and green hold, for each pixel, where to read the source image: s = x / W,
// t = 1 - y / H for a source raster position (x, y) (the origin at the
// bottom-left corner, y up, as Nuke's). Alpha is 1 where the map holds a
// position, 0 where none exists (red, green and blue then 0).
//  - undistort: applied to lensrt's image, gives the ideal pinhole image
//    with the fitted fx, fy, cx, cy (each pixel's ray projected exactly
//    through the lens);
//  - distort: applied to an ideal pinhole image with those intrinsics,
//    gives lensrt's image (each pixel's chief ray).
// Both from the exact projection, not the fitted coefficients.
Image stMap(const Calibration& c, bool undistort, Warnings& warnings);

}  // namespace lensrt
