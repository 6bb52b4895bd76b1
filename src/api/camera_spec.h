// What the camera is asked to be, parsed once at the edge (the option table,
// api/option_table.h): the model, the lens and its aperture and focus, the
// sensor, the exposure. camera_factory.h turns it into a Camera.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "api/keyframes.h"
#include "camera/exposure.h"
#include "camera/lens_movements.h"
#include "core/vec.h"
#include "optics/coating.h"

namespace lensrt {

// The four models (api/camera_models.h lists them with their names).
enum class CameraModel { Pinhole, Thin, Thick, Lens };

// What a pixel records (camera/camera.h's CameraInfo::film).
enum class FilmQuantity { Radiance, Irradiance };

struct CameraSpec {
  CameraModel model = CameraModel::Pinhole;
  std::string lens;  // a lens file or a name from the library; empty: none
  // The f-number: a number, keyframes read at the scene's time, or neither
  // (the lens wide open, else 2.8).
  std::optional<double> fNumber;
  Keyframes fNumberKeys;
  // The focus distance from the entrance pupil in metres (infinity allowed),
  // keyframes, or neither: auto (what focusPixel, else the centre, sees).
  std::optional<double> focusMetres;
  Keyframes focusKeys;
  std::optional<Vec2d> focusPixel;  // raster pixel for auto focus
  Vec2d sensorMm{36.0, 24.0};       // the sensor, cropped to the raster's aspect ratio
  int blades = 0;                   // 0: a round aperture
  double bladeRotationDegrees = 0.0;
  std::filesystem::path apertureMask;  // a grey-scale image over the full lens's stop; empty: none
  std::optional<double> focalLengthMm;
  ExposureMode exposure = ExposureMode::Normalized;
  std::optional<double> iso;                         // physical exposure's ISO speed (default 100)
  bool dispersion = true;                            // trace each sample at its wavelength
  bool diffraction = false;                          // bend each ray by the stop's far field
  std::optional<Coating> coatings;                   // none: lossless glass
  std::optional<FilmQuantity> film;                  // none: the model's default
  LensMovements movements;                           // the film's shift and tilt (camera/lens_movements.h)
  std::filesystem::path lensDir = defaultLensDir();  // the lens library

  bool autoFocus() const { return !focusMetres && focusKeys.empty(); }
  // The library installed with lensrt (LENSRT_LENS_DIR), empty without one.
  static std::filesystem::path defaultLensDir();
};

}  // namespace lensrt
