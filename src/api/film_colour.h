// How a render's film records colour, from the camera options: spectral transport
// through a film response (render/film_response.h) built from the sensor's response
// curves, the white balance and the output space, or RGB transport (--spectral off).
// The responses, white balances and spaces: docs/design/spectral-transport.md.
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
