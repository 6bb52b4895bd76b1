// `lensrt sensor list [--json]`: the sensors --sensor-params names, with the
// parameters of each (the JSON is what a sensor file holds, so a preset
// printed with --json is a starting point for one's own).
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/command.h"
#include "sensor/sensor_params.h"

namespace lensrt {
namespace {

nlohmann::json sensorJson(const SensorParams& p) {
  return {{"name", p.name},
          {"full_well_e", p.fullWellE},
          {"gain_dn_per_e", p.gainDnPerE},
          {"base_iso", p.baseIso},
          {"read_noise_e", p.readNoiseE},
          {"dark_current_e_per_s", p.darkCurrentEPerS},
          {"prnu_percent", p.prnuPercent},
          {"dsnu_percent", p.dsnuPercent},
          {"adc_bits", p.adcBits},
          {"black_level_dn", p.blackLevelDn},
          {"quantum_efficiency", p.quantumEfficiency},
          {"fixed_pattern_seed", p.fixedPatternSeed}};
}

int runList(bool json) {
  if (json) {
    nlohmann::json all = nlohmann::json::array();
    for (const SensorParams& p : sensorPresets()) all.push_back(sensorJson(p));
    std::cout << all.dump(2) << "\n";
    return 0;
  }
  fmt::print("{:<16} {:>10} {:>8} {:>8} {:>9} {:>6} {:>6} {:>5} {:>7} {:>5}\n", "sensor", "full well", "DN/e",
             "read e", "dark e/s", "PRNU%", "DSNU%", "bits", "black", "QE");
  for (const SensorParams& p : sensorPresets())
    fmt::print("{:<16} {:>10g} {:>8g} {:>8g} {:>9g} {:>6g} {:>6g} {:>5} {:>7g} {:>5g}\n", p.name, p.fullWellE,
               p.gainDnPerE, p.readNoiseE, p.darkCurrentEPerS, p.prnuPercent, p.dsnuPercent, p.adcBits,
               p.blackLevelDn, p.quantumEfficiency);
  fmt::print(
      "(--noise on --sensor-params NAME, or a .json file of these fields: lensrt sensor list --json)\n");
  return 0;
}

}  // namespace

CommandAction addSensorCommand(CLI::App& app, const CommandContext&) {
  CLI::App* sensorApp =
      app.add_subcommand("sensor", "Sensor tools: the sensors --noise on can read out through");
  sensorApp->require_subcommand(1);
  CLI::App* list =
      sensorApp->add_subcommand("list", "List the sensor presets of --sensor-params with their parameters");
  auto json = std::make_shared<bool>(false);
  list->add_flag("--json", *json, "Print JSON: one object per preset, the fields of a sensor file");
  return [json] { return runList(*json); };
}

}  // namespace lensrt
