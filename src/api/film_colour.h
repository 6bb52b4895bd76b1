// How a render's film records colour, from the camera options: spectral
// transport through a film response (render/film_response.h) built from the
// sensor's response curves, the white balance and the output space, or RGB
// transport (--spectral off).
//
// - cie1931 (the default response): XYZ, adapted (Bradford) from the white
//   balance's illuminant to the output space's white, then into its RGB.
// - A camera (--sensor-response NAME|FILE.csv): its R, G, B curves, through a
//   3x3 matrix to XYZ fitted over the ColorChecker under the white balance's
//   illuminant, then as cie1931; or its own RGB (--output-space camera).
// - The white balance: none (the illuminant of RGB (1, 1, 1) light, D65),
//   KELVIN (CIE daylight from 4000 K, a black body below), or auto (the colour
//   of the scene's most powerful light: upsampled, times D65). A reflectance
//   of 1 under that illuminant records the output's white exactly, so a grey
//   card stays grey.
// - The output space: srgb (linear Rec. 709), rec2020, acescg, xyz.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "api/colour_spec.h"
#include "core/warnings.h"
#include "render/film_response.h"
#include "sensor/camera_rgb.h"
#include "sensor/sensor_response.h"

namespace lensrt {

struct FilmColour {
  std::shared_ptr<const FilmResponse> response;  // none for --spectral off
  // A camera response's own RGB (sensor/camera_rgb.h), for the sensor's
  // readout and the raw file; none for cie1931 and RGB transport, whose
  // image RGB is the sensor's.
  std::optional<CameraRgb> camera;
};

// `sceneLight`: the colour of the scene's dominant light
// (RenderJob::dominantLightColour), for --white-balance auto. Throws
// UsageError for bad options.
FilmColour filmColour(const ColourSpec& colour, const std::optional<Rgb>& sceneLight, Warnings& warnings);

// "rgb", or "spectral:" and the response's description: part of a render's
// identity (a checkpoint resumes, and tiles merge, only with the same transport).
std::string transportDescription(const FilmResponse* response);

// The checks that need the response's file (an unknown name or a bad file
// fails before the scene loads). Throws UsageError / InputError.
void checkColourSpec(const ColourSpec& colour);

// A camera's RGB to XYZ: the least-squares 3x3 over the ColorChecker's 24
// patches lit by `illuminant` (as pbrt-v4's PixelSensor fits it).
Mat3d fitCameraToXyz(const SensorResponse& sensor, const std::function<double(double)>& illuminant);

}  // namespace lensrt
