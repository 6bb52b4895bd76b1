// A sensor's spectral response: what each of its three channels records per
// unit of light at each wavelength. The named responses are the CIE 1931
// observer (a colorimetric film: X, Y, Z) and the measured R, G, B of real
// camera bodies (data/sensor-responses, compiled in); a user's own comes from
// a CSV file (response_csv.h).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/vec.h"

namespace lensrt {

inline constexpr std::string_view kCie1931Response = "cie1931";

struct SensorResponse {
  std::string name;   // "cie1931", a camera's ("nikon-d850"), or the file as given
  std::string maker;  // a camera's maker and model, where known ("Nikon", "D850")
  std::string model;
  std::string source;  // where the curves come from, for credits and plots
  // The CIE observer, whose channels are X, Y, Z (then to an output space)
  // rather than a camera's R, G, B (then through a fitted matrix).
  bool cie1931 = false;
  std::vector<double> wavelengthsNm;  // strictly increasing
  std::vector<Vec3d> rgb;             // the three channels at each wavelength, >= 0

  // The three channels at any wavelength: linear between samples, 0 outside.
  Vec3d at(double nm) const;
  // The tabulated wavelength where each channel is largest (the first, on ties).
  Vec3d peakWavelengthsNm() const;
};

// The names `namedSensorResponse` takes: cie1931 first, then the cameras.
std::vector<std::string> sensorResponseNames();

// cie1931 (the observer's 1 nm table, 360-830 nm) or a camera. Throws
// InputError naming the known responses for another name.
SensorResponse namedSensorResponse(std::string_view name);

// A file when the argument ends in .csv or holds a path separator (read by
// readResponseCsv), else a name as namedSensorResponse takes it.
SensorResponse loadSensorResponse(std::string_view nameOrFile);

}  // namespace lensrt
