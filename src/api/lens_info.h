// `lensrt lens info`: every first-order quantity of a lens, stopped down and
// focused, with its exit-pupil efficiency, colour and transmittance; the
// command prints it as text or JSON (and the Python module to come returns
// the same JSON as a dict).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/warnings.h"
#include "optics/chromatic.h"
#include "optics/coating.h"
#include "optics/lens_system.h"
#include "optics/paraxial.h"

namespace lensrt {

struct LensInfoSettings {
  double sensorWidthMm = 36.0, sensorHeightMm = 24.0;
  std::optional<double> fNumber;              // stop down to it; none: wide open
  double focusMetres = 0.0;                   // from the entrance pupil; kInfinity allowed
  std::optional<double> circleOfConfusionMm;  // none: the diagonal / 1500
  Coating coating = Coating::None;            // for the axial transmittance
};

struct LensInfo {
  explicit LensInfo(LensSystem stoppedDown) : lens(std::move(stoppedDown)) {}
  LensSystem lens;  // stopped down
  double widestFNumber = 0.0;
  LensInfoSettings settings;
  double filmDistanceMm = 0.0;  // exact-ray focus, rear vertex -> film
  Conjugate conjugate;          // the paraxial one
  FieldOfView fov;
  double closestFocusMm = 0.0;
  double circleOfConfusionMm = 0.0;
  double hyperfocalMm = 0.0, nearMm = 0.0, farMm = 0.0;  // from the entrance pupil
  double exitPupilEfficiency = 0.0;
  double axialColorMm = 0.0;
  std::optional<LateralColor> lateralColor;  // at the half diagonal
  double axialTransmittance = 0.0;
  double halfDiagonalMm() const;
};

// Throws what the optics throw for a lens that cannot be stopped down or
// focused so (InputError naming the lens).
LensInfo lensInfo(const LensPrescription& design, const LensInfoSettings& settings, Warnings& warnings);

// `lens info --json`: distances in mm unless named _m, null at infinity.
nlohmann::json lensInfoJson(const LensInfo& info, const std::vector<std::string>& warnings);

}  // namespace lensrt
