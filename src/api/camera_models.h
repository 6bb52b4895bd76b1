// The camera models: the registry that `render`'s --camera, `compare`'s four
// renders, the report and Python read. Each model's file
// (api/<name>_model.cpp) holds its create function from the settings every
// model shares (CameraBuild, made by api/camera_factory.h's makeCamera) and
// the rows of the option table only it takes.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/camera_spec.h"
#include "api/flare_spec.h"
#include "api/option_table.h"
#include "camera/aperture.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "camera/lens_camera.h"
#include "core/transform.h"
#include "core/warnings.h"
#include "optics/paraxial.h"
#include "optics/prescription.h"

namespace lensrt {

// What makeCamera has worked out for every model: the film, the exposure,
// the lens and its paraxial data, the f-number, focal length and focus.
struct CameraBuild {
  const CameraSpec& spec;
  const FlareSpec& flare;
  const Transform& worldFromCamera;
  const FilmGeometry& film;
  const Exposure& exposure;
  const std::optional<LensPrescription>& lens;
  const std::optional<ParaxialData>& paraxial;
  std::optional<double> keyedFNumber;  // the f-number asked for (at the scene's time), if any
  double fNumber = 0;                  // the one to use
  double focalLengthMm = 0;
  double yfovInfinity = 0;  // radians, focused at infinity
  double focusMetres = 0;   // infinity allowed
  ApertureShape aperture;
  std::string lensName;     // empty without a lens
  LensMovements movements;  // checked against the film
  Warnings& warnings;
  const LensCamera** flareLens;  // set to a full lens that makes stray light; may be null
};

struct CameraModelInfo {
  CameraModel model;
  std::string name;         // "pinhole", as --camera takes it
  std::string description;  // one line for help and reports
  bool needsLens = false;   // refuses to be made without --lens
  std::unique_ptr<Camera> (*create)(const CameraBuild& build) = nullptr;
  // Appends the rows of the option table that only this model takes; may be null.
  void (*addRows)(std::vector<Option>& table) = nullptr;
};

// In the order `compare` renders them: the full lens, the reference, last.
const std::vector<CameraModelInfo>& cameraModels();
const CameraModelInfo& cameraModel(CameraModel model);
const std::string& cameraModelName(CameraModel model);

}  // namespace lensrt
