#include "sensor/sensor_params.h"

#include <fmt/core.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"

namespace lensrt {
namespace {

// Sensors of three sizes of camera, from published photon transfer data of
// their classes (small pixels hold few electrons and read with little noise).
SensorParams preset(std::string name, double fullWell, double gain, double readNoise, double dark, int bits,
                    double black, double qe) {
  SensorParams p;
  p.name = std::move(name);
  p.fullWellE = fullWell;
  p.gainDnPerE = gain;
  p.readNoiseE = readNoise;
  p.darkCurrentEPerS = dark;
  p.adcBits = bits;
  p.blackLevelDn = black;
  p.quantumEfficiency = qe;
  return p;
}

constexpr std::size_t kMaxSensorFileBytes = 1 << 20;

}  // namespace

const std::vector<SensorParams>& sensorPresets() {
  static const std::vector<SensorParams> presets = {
      SensorParams{},                                                  // default: an APS-C-like 12-bit sensor
      preset("full-frame", 60000.0, 0.25, 3.0, 0.2, 14, 512.0, 0.55),  // large pixels, 14 bits
      preset("smartphone", 6000.0, 0.15, 2.0, 2.0, 10, 64.0, 0.6),     // small pixels, 10 bits
      preset("machine-vision", 10500.0, 0.38, 7.0, 5.0, 12, 0.0, 0.65),  // global shutter, no black offset
  };
  return presets;
}

std::string sensorParamsProblem(const SensorParams& p) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  const auto nonNegative = [](double v) { return std::isfinite(v) && v >= 0.0; };
  // Upper bounds far beyond any sensor keep every product finite.
  if (!positive(p.fullWellE) || p.fullWellE > 1e9) return "full_well_e must be positive, at most 1e9";
  if (!positive(p.gainDnPerE) || p.gainDnPerE > 1e6) return "gain_dn_per_e must be positive, at most 1e6";
  if (!(p.baseIso >= 1 && p.baseIso <= 1e7)) return "base_iso must be from 1 to 1e7";
  if (!nonNegative(p.readNoiseE) || p.readNoiseE > 1e6) return "read_noise_e must be from 0 to 1e6";
  if (!nonNegative(p.darkCurrentEPerS) || p.darkCurrentEPerS > 1e9)
    return "dark_current_e_per_s must be from 0 to 1e9";
  if (!nonNegative(p.prnuPercent) || p.prnuPercent > 100) return "prnu_percent must be from 0 to 100";
  if (!nonNegative(p.dsnuPercent) || p.dsnuPercent > 1000) return "dsnu_percent must be from 0 to 1000";
  if (p.adcBits < 1 || p.adcBits > 16) return "adc_bits must be from 1 to 16";
  if (!nonNegative(p.blackLevelDn) || p.blackLevelDn >= p.maxDn())
    return fmt::format("black_level_dn must be from 0 to below the ADC's maximum {}", p.maxDn());
  if (!positive(p.quantumEfficiency) || p.quantumEfficiency > 1)
    return "quantum_efficiency must be in (0, 1]";
  return {};
}

SensorParams parseSensorParams(std::string_view text, const std::string& file) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, fmt::format("not valid JSON (at byte {})", e.byte));
  } catch (const nlohmann::json::exception& e) {
    // A number too large for a double, say: the library's words after its tag.
    const std::string what = e.what();
    const std::size_t tagEnd = what.find("] ");
    throw InputError(file,
                     "not valid JSON: " + (tagEnd == std::string::npos ? what : what.substr(tagEnd + 2)));
  }
  if (!j.is_object()) throw InputError(file, "expected a JSON object of sensor parameters");
  SensorParams p;
  const auto number = [&](const char* key, double& out) {
    const auto it = j.find(key);
    if (it == j.end()) throw InputError(file, fmt::format("missing field \"{}\"", key));
    if (!it->is_number()) throw InputError(file, fmt::format("field \"{}\" must be a number", key));
    out = it->get<double>();
  };
  number("full_well_e", p.fullWellE);
  number("gain_dn_per_e", p.gainDnPerE);
  number("base_iso", p.baseIso);
  number("read_noise_e", p.readNoiseE);
  number("dark_current_e_per_s", p.darkCurrentEPerS);
  number("prnu_percent", p.prnuPercent);
  number("dsnu_percent", p.dsnuPercent);
  double bits = 0.0;
  number("adc_bits", bits);
  if (bits != std::floor(bits) || bits < 1 || bits > 16)
    throw InputError(file, "field \"adc_bits\" must be an integer from 1 to 16");
  p.adcBits = int(bits);
  number("black_level_dn", p.blackLevelDn);
  number("quantum_efficiency", p.quantumEfficiency);
  if (const auto it = j.find("name"); it != j.end()) {
    if (!it->is_string()) throw InputError(file, "field \"name\" must be a string");
    p.name = it->get<std::string>();
  } else {
    p.name = std::filesystem::path(file).stem().string();
  }
  if (const auto it = j.find("fixed_pattern_seed"); it != j.end()) {
    if (!it->is_number_unsigned())
      throw InputError(file, "field \"fixed_pattern_seed\" must be an integer >= 0");
    p.fixedPatternSeed = it->get<std::uint64_t>();
  }
  for (const auto& [key, value] : j.items()) {
    static const char* const known[] = {"name",           "full_well_e",        "gain_dn_per_e",
                                        "base_iso",       "read_noise_e",       "dark_current_e_per_s",
                                        "prnu_percent",   "dsnu_percent",       "adc_bits",
                                        "black_level_dn", "quantum_efficiency", "fixed_pattern_seed"};
    if (std::find(std::begin(known), std::end(known), key) == std::end(known))
      throw InputError(file, fmt::format("unknown field \"{}\"", key));
  }
  if (const std::string why = sensorParamsProblem(p); !why.empty()) throw InputError(file, why);
  return p;
}

SensorParams sensorParams(const std::string& nameOrFile) {
  for (const SensorParams& p : sensorPresets())
    if (p.name == nameOrFile) return p;
  const std::filesystem::path path(nameOrFile);
  if (path.extension() != ".json") {
    std::string names;
    for (const SensorParams& p : sensorPresets()) names.append(names.empty() ? "" : ", ").append(p.name);
    throw UsageError("--sensor-params",
                     fmt::format("unknown sensor '{}' (presets: {}; or a .json file)", nameOrFile, names));
  }
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(nameOrFile, "no such sensor file");
  if (std::filesystem::file_size(path, ec) > kMaxSensorFileBytes)
    throw InputError(nameOrFile, "too large for a sensor file (over 1 MiB)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw InputError(nameOrFile, "cannot read");
  return parseSensorParams(text.str(), nameOrFile);
}

}  // namespace lensrt
