// `lensrt sensor list [--json]`: the sensors --sensor-params names, with the
// parameters of each (the JSON is what a sensor file holds, so a preset
// printed with --json is a starting point for one's own), and the spectral
// responses with their cameras, ranges and peaks.
// `lensrt sensor plot NAME|FILE.csv -o curves.svg`: a response's curves.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "api/output_file.h"
#include "app/command.h"
#include "core/error.h"
#include "report/response_plot.h"
#include "sensor/sensor_params.h"
#include "sensor/sensor_response.h"

namespace lensrt {
namespace {

nlohmann::ordered_json sensorJson(const SensorParams& p) {
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

// Cameras have a maker and model; the CIE observer is described by its source.
std::string responseDescription(const SensorResponse& r) {
  return r.maker.empty() ? r.source : fmt::format("{} {}", r.maker, r.model);
}

nlohmann::ordered_json responseJson(const SensorResponse& r) {
  const Vec3d peak = r.peakWavelengthsNm();
  nlohmann::ordered_json j = {{"name", r.name}, {"cie1931", r.cie1931}};
  if (!r.maker.empty()) j["maker"] = r.maker;
  if (!r.model.empty()) j["model"] = r.model;
  j["source"] = r.source;
  j["min_nm"] = r.wavelengthsNm.front();
  j["max_nm"] = r.wavelengthsNm.back();
  j["peak_nm"] = {peak.x, peak.y, peak.z};
  return j;
}

int runList(bool json) {
  std::vector<SensorResponse> responses;
  for (const std::string& name : sensorResponseNames()) responses.push_back(namedSensorResponse(name));
  if (json) {
    nlohmann::ordered_json presets = nlohmann::ordered_json::array(),
                           curves = nlohmann::ordered_json::array();
    for (const SensorParams& p : sensorPresets()) presets.push_back(sensorJson(p));
    for (const SensorResponse& r : responses) curves.push_back(responseJson(r));
    std::cout << nlohmann::ordered_json{{"sensor_params", presets}, {"responses", curves}}.dump(2) << "\n";
    return 0;
  }
  fmt::print("{:<16} {:>10} {:>8} {:>8} {:>9} {:>6} {:>6} {:>5} {:>7} {:>5}\n", "sensor", "full well", "DN/e",
             "read e", "dark e/s", "PRNU%", "DSNU%", "bits", "black", "QE");
  for (const SensorParams& p : sensorPresets())
    fmt::print("{:<16} {:>10g} {:>8g} {:>8g} {:>9g} {:>6g} {:>6g} {:>5} {:>7g} {:>5g}\n", p.name, p.fullWellE,
               p.gainDnPerE, p.readNoiseE, p.darkCurrentEPerS, p.prnuPercent, p.dsnuPercent, p.adcBits,
               p.blackLevelDn, p.quantumEfficiency);
  fmt::print(
      "(--noise on --sensor-params NAME, or a .json file of these fields: lensrt sensor list --json)\n\n");
  fmt::print("{:<24} {:<36} {:>9} {:>16}\n", "response", "camera", "range nm", "peaks r,g,b nm");
  for (const SensorResponse& r : responses) {
    const Vec3d peak = r.peakWavelengthsNm();
    fmt::print("{:<24} {:<36} {:>9} {:>16}\n", r.name, responseDescription(r),
               fmt::format("{:g}-{:g}", r.wavelengthsNm.front(), r.wavelengthsNm.back()),
               fmt::format("{:g},{:g},{:g}", peak.x, peak.y, peak.z));
  }
  fmt::print(
      "(cie1931: the CIE observer's xbar, ybar, zbar; or a .csv file of wavelength_nm,r,g,b rows. "
      "lensrt sensor plot NAME -o curves.svg draws one)\n");
  return 0;
}

int runPlot(const std::string& response, const std::string& output) {
  if (std::filesystem::path(output).extension() != ".svg")
    throw UsageError("-o",
                     fmt::format("sensor plot writes SVG: expected a file ending in .svg, got '{}'", output));
  const SensorResponse r = loadSensorResponse(response);
  noteCreatedFolder(createFolderFor(output), false);
  plotSensorResponse(r).write(output);
  fmt::print(stderr, "lensrt: wrote {}\n", output);
  return 0;
}

}  // namespace

CommandAction addSensorCommand(CLI::App& app, const CommandContext&) {
  CLI::App* sensorApp = app.add_subcommand(
      "sensor", "Sensor tools: the sensors --noise on can read out through, and spectral responses");
  sensorApp->require_subcommand(1);
  CLI::App* list = sensorApp->add_subcommand(
      "list", "List the sensor presets of --sensor-params with their parameters, and the spectral responses");
  auto json = std::make_shared<bool>(false);
  list->add_flag("--json", *json,
                 "Print JSON: sensor_params, one object per preset with the fields of a sensor file, and "
                 "responses, one per spectral response");
  struct PlotOptions {
    std::string response, output;
  };
  auto plot = std::make_shared<PlotOptions>();
  CLI::App* plotApp =
      sensorApp->add_subcommand("plot", "Draw a spectral response's three curves against wavelength (SVG)");
  plotApp
      ->add_option("response", plot->response,
                   "A response of lensrt sensor list, or a wavelength_nm,r,g,b .csv file")
      ->required();
  plotApp->add_option("-o,--output", plot->output, "Output SVG file")->required();
  return
      [list, json, plot] { return list->parsed() ? runList(*json) : runPlot(plot->response, plot->output); };
}

}  // namespace lensrt
