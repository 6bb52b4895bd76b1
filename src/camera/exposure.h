// From film irradiance to the recorded pixel value.
//
// Every model computes the irradiance ratio E / L (dimensionless: the
// integral of cos(th_film) cos(th_pupil) / d^2 over its pupil); the exposure
// scale turns it into the value written to the image:
//  - normalized (default): value = L * (E/L) / (pi / (4 N^2)), N the model's
//    own nominal f-number. An ideal lens focused at infinity viewing radiance L
//    on axis records exactly L at every f-number; off axis it records
//    L cos^4(theta), and focused closer the bellows factor (f/v)^2 darkens it
//    as it darkens a real camera. The pinhole records L cos^4(theta).
//  - physical: value = H_v * ISO / 78, the photometric exposure H_v = 683 lm/W
//    * E * t (lux seconds; scene radiance in W/(sr m^2) as the README states)
//    scaled so that 1.0 is the ISO 12232 saturation exposure H_sat = 78 / ISO.
//    Reciprocity holds: equal N^2 / t gives an equal value.
#pragma once

#include <string>

namespace lensrt {

enum class ExposureMode { Normalized, Physical };

struct Exposure {
  ExposureMode mode = ExposureMode::Normalized;
  double shutterSeconds = 0.01;
  double iso = 100.0;
};

inline constexpr double kLuminousEfficacy = 683.0;      // lm/W, the README's photometric conversion
inline constexpr double kIsoSaturationConstant = 78.0;  // ISO 12232 saturation-based speed

// The ideal on-axis irradiance ratio E/L of an f/N lens focused at infinity: pi / (4 N^2).
double idealIrradianceRatio(double fNumber);

// Multiplies E/L to give the recorded value per unit radiance; `fNumber` is
// the model's own nominal f-number. Throws std::invalid_argument for
// non-positive values.
double exposureScale(const Exposure& exposure, double fNumber);

// "normalized" or "physical 0.01s ISO100".
std::string describe(const Exposure& exposure);

}  // namespace lensrt
