// What a sensor does with light, as --sensor-params gives it: a named preset
// or a JSON file. Units are in the names: e (electrons), DN (digital numbers
// of the ADC), percent.
//
//   {"name": "my-sensor", "full_well_e": 20000, "gain_dn_per_e": 0.2,
//    "base_iso": 100, "read_noise_e": 3.0, "dark_current_e_per_s": 0.5,
//    "prnu_percent": 0.5, "dsnu_percent": 10, "adc_bits": 12,
//    "black_level_dn": 64, "quantum_efficiency": 0.5}
//
// Every field but "name" and "fixed_pattern_seed" is required.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lensrt {

struct SensorParams {
  std::string name = "default";
  double fullWellE = 20000.0;          // electrons a pixel holds
  double gainDnPerE = 0.2;             // conversion gain at the base ISO (the ADC's DN per electron)
  double baseIso = 100.0;              // analog gain 1; ISO s multiplies the gain by s / base
  double readNoiseE = 3.0;             // standard deviation of the readout, electrons
  double darkCurrentEPerS = 0.5;       // mean dark electrons per second of exposure
  double prnuPercent = 0.5;            // photo-response non-uniformity: per-pixel gain spread (1 sigma)
  double dsnuPercent = 10.0;           // dark-signal non-uniformity: per-pixel dark-current spread (1 sigma)
  int adcBits = 12;                    // the ADC's range is [0, 2^bits - 1]
  double blackLevelDn = 64.0;          // DN of zero electrons
  double quantumEfficiency = 0.5;      // electrons per photon (one value until spectral responses)
  std::uint64_t fixedPatternSeed = 1;  // the sensor's own: the same PRNU/DSNU in every render

  double maxDn() const { return double((std::uint64_t{1} << adcBits) - 1); }
};

// The presets `--sensor-params NAME` takes, first the default.
const std::vector<SensorParams>& sensorPresets();

// A preset by name, or a .json file. Throws UsageError("--sensor-params")
// naming the presets for an unknown name, InputError(file, ...) for a bad file.
SensorParams sensorParams(const std::string& nameOrFile);

// Parses the JSON text of a sensor file (`file` names it in errors): every
// field present, numeric and in range. Throws InputError.
SensorParams parseSensorParams(std::string_view text, const std::string& file);

// Why these parameters cannot describe a sensor (a non-positive full well,
// 0 or more than 16 ADC bits, a black level at or above the ADC's range, ...),
// or empty.
std::string sensorParamsProblem(const SensorParams& params);

}  // namespace lensrt
