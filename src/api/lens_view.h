// Options and set-up shared by `lens diagram` and `lens plot`: the lens,
// stopped down and focused, with the sensor that sets the field.
#pragma once

#include <optional>
#include <string>

#include "api/lens_loading.h"
#include "core/vec.h"
#include "core/warnings.h"
#include "optics/lens_system.h"

namespace lensrt {

struct LensViewOptions {
  std::string lens;
  std::string output;
  std::optional<double> fNumber;
  std::string focus = "inf";
  std::string sensor = "36x24";
  std::string coatings;  // none|single|multi: the traces carry Fresnel losses; empty: lossless
};

struct LensView {
  LensSystem lens;
  double widestFNumber = 0.0;
  double focusMm = 0.0;         // from the entrance pupil; kInfinity allowed
  double filmDistanceMm = 0.0;  // rear vertex -> film
  double sensorWidthMm = 36.0, sensorHeightMm = 24.0;
  double halfDiagonalMm() const;
  double filmZ() const { return lens.rearZ() + filmDistanceMm; }
  std::string focusText() const;  // "infinity" or "2 m"
  // "EFL 50.36 mm, f/2.03, focus infinity, sensor 36 x 24 mm"
  std::string summary() const;
};

// Validates the option values (UsageError: exit 2), loads, stops
// down and focuses the lens (InputError: exit 1). An empty output is not checked.
LensView prepareLensView(const LensViewOptions& options, Warnings& warnings);
// The same for a lens already loaded (options.lens and .output unused).
LensView prepareLensView(const UserLens& lens, const LensViewOptions& options, Warnings& warnings);

// --sensor WIDTHxHEIGHT in mm (no names: lens commands state sizes), and
// --focus in metres or inf, returned in mm (kInfinity allowed). Throw UsageError.
Vec2d parseSensorSize(const std::string& text);
double parseFocusDistanceMm(const std::string& text);
double parseFocusMetres(const std::string& text);
// --fstop: positive and finite when given. Throws UsageError.
void checkFNumber(const std::optional<double>& fNumber);

// The output must be an .svg path (UsageError) in an existing,
// writable directory (InputError).
void checkSvgOutput(const std::string& output);

// Any output file: its directory must exist and be writable (InputError),
// checked before the work so a mistake costs no tracing.
void checkOutputDirectory(const std::string& output);

}  // namespace lensrt
