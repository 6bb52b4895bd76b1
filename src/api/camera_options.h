// The camera flags of `lensrt render` and the factory that turns them (with
// the glTF camera) into one of the four models.
//
//   --camera pinhole|thin|thick|lens   --lens FILE|NAME   --fstop N
//   --focus METRES|auto|inf   --focus-pixel X,Y   --sensor WxH|NAME
//   --blades N   --blade-rotation DEG   --aperture-mask FILE   --focal-length MM
//   --exposure normalized|physical   --shutter SECONDS   --iso N
//   --dispersion on|off
//   --coatings none|single|multi
//   --film radiance|irradiance
//   --noise on|off   --sensor-params NAME|FILE.json
//
// Bad values are usage errors (UsageError naming the flag: exit 2 in the
// command line); app/camera_flags.h registers the flags.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "api/keyframes.h"
#include "camera/camera.h"
#include "core/ray.h"
#include "core/warnings.h"
#include "image/image.h"
#include "render/shutter_timing.h"
#include "scene/scene_desc.h"

namespace lensrt {

struct CameraOptions {
  std::string model = "pinhole";
  std::string lens;  // a path, or a name from the lens library; empty: none
  std::optional<double> fNumber;
  std::string fNumberKeyframes;  // --fstop SECONDS:N,...: read at timeSeconds, in place of fNumber
  std::string focus = "auto";    // also keyframes SECONDS:METRES,... (api/keyframes.h)
  std::string focusPixel;        // "X,Y" raster pixel for --focus auto; empty: the centre
  std::string sensor = "full-frame";
  int blades = 0;
  double bladeRotationDegrees = 0.0;
  std::string apertureMask;  // grey-scale image over the full lens's stop; empty: none
  std::optional<double> focalLengthMm;
  std::string exposure = "normalized";
  std::string shutter;  // seconds, "0.01" or "1/100"; empty: 1/100; 0: an instant
  // Time (render/shutter_timing.h): --shutter-curve box|trapezoid:F,
  // --rolling-shutter SECONDS (empty: a global shutter) read out --readout
  // top-down|bottom-up|left-right|right-left.
  std::string shutterCurve = "box";
  std::string rollingShutter;
  std::string readout = "top-down";
  std::optional<double> iso;
  std::string dispersion = "on";   // the full lens traces each sample at its wavelength
  std::string coatings;            // --coatings none|single|multi for the full lens; empty: lossless glass
  std::string flare = "off";       // --flare on: stray light in the full lens (its surfaces reflect)
  int flareBounces = 2;            // --flare-bounces: the most reflections a path takes (0, 2 or 4)
  double barrelReflectance = 0.0;  // --barrel-reflectance: the barrel's diffuse reflectance, in [0, 1)
  // "radiance", "irradiance", or empty for the model's default: radiance for
  // the pinhole, irradiance for thin, thick and lens (which refuse radiance).
  std::string film;
  // --spectral on: light is carried at four wavelengths per sample
  // (render/wavelengths.h); off: in RGB.
  std::string spectral = "on";
  std::string sensorResponse;        // --sensor-response NAME|FILE.csv; empty: cie1931
  std::string whiteBalance;          // --white-balance auto|none|KELVIN; empty: the response's default
  std::string outputSpace = "srgb";  // --output-space srgb|rec2020|acescg|xyz|camera
  std::string noise = "off";         // --noise on: the sensor's readout (api/sensor_readout.h)
  std::string sensorParams;          // --sensor-params NAME|FILE.json; empty: the default sensor
  std::filesystem::path lensDir;     // the library; addCameraOptions sets the installed one
  // When the shutter opens (the scene's --time; RenderJob sets it): where
  // keyframed settings are read.
  double timeSeconds = 0.0;
};

// --focus: "auto" -> nullopt, "inf"/"infinity" -> infinity, else metres > 0.
// Throws UsageError.
// --fstop SECONDS:N,... (api/keyframes.h). Throws UsageError.
Keyframes fNumberKeyframes(const std::string& text);
// Keyframes (api/keyframes.h, "0:1.2,2:4") give their value at `seconds`.
std::optional<double> parseFocus(const std::string& text, double seconds = 0.0);
// --focus-pixel "X,Y" in pixels. Throws UsageError.
Vec2d parseFocusPixel(const std::string& text);

// Sensor size in mm of "WxH" (e.g. 36x24) or a name: full-frame 36x24,
// aps-c 23.6x15.6, mft 17.3x13, 1in 13.2x8.8. Throws UsageError.
Vec2d parseSensor(const std::string& text);
// Seconds from "0.004", "1/250" or "2". Throws UsageError.
double parseShutter(const std::string& text);
// --shutter of these options, else the exposure's default (1/100 s).
double shutterSeconds(const CameraOptions& options);
// How long a frame records the scene (--shutter plus --rolling-shutter's
// readout): the span a moving scene is loaded for.
double recordedSpanSeconds(const CameraOptions& options);
// When each sample is taken (render/shutter_timing.h), from --shutter,
// --shutter-curve, --rolling-shutter and --readout. Throws UsageError.
ShutterTiming shutterTiming(const CameraOptions& options);

// The film: the sensor cropped to the raster's aspect ratio (square pixels),
// as a camera's video or crop modes do.
FilmGeometry cameraFilm(const CameraOptions& options, int width, int height);

// The distance (metres, along the unit world-space ray) to the first surface
// the ray hits; nullopt when it hits nothing. Used for --focus auto.
using HitDistance = std::function<std::optional<double>(const Ray&)>;

// Every value in range and every name known, as the command line's flag
// checks have it (the Python module has no such checks). Throws UsageError.
void checkCameraOptions(const CameraOptions& options);

// Builds the model (checkCameraOptions first). `film` gives the raster size; its sensor is replaced by
// cameraFilm's. With --lens the simpler models are derived from the lens's
// paraxial data (thin: f = EFL and its f-number; thick: its cardinal points and
// pupils; pinhole: the lens's field of view at that focus). Without it, f is
// --focal-length, else the glTF camera's yfov over the sensor height.
std::unique_ptr<Camera> makeCamera(const CameraOptions& options, const CameraDesc& gltfCamera,
                                   FilmGeometry film, const HitDistance& hitDistance, Warnings& warnings);

// lensrt:camera_model, lensrt:lens, lensrt:f_number, lensrt:focus_m,
// lensrt:focal_length_mm, lensrt:sensor_mm, lensrt:exposure, lensrt:dispersion,
// lensrt:coatings, lensrt:film.
// and OpenEXR's standard attributes, which the image layer writes typed:
// aperture (f-number), focus (m), expTime (s) and isoSpeed (physical
// exposure only), worldToCamera, chromaticities (Rec.709, D65).
ImageMetadata cameraMetadata(const Camera& camera);
ImageMetadata standardCameraAttributes(const Camera& camera);

}  // namespace lensrt
