#include "app/lens_wave_flags.h"

#include <fmt/core.h>

#include <filesystem>
#include <iostream>

#include "api/output_file.h"
#include "api/text_file.h"
#include "app/lens_subcommands.h"
#include "app/lens_view_flags.h"
#include "app/option_checks.h"

namespace lensrt {

void addLensWaveOptions(CLI::App& command, LensWaveCommandOptions& o) {
  addLensViewOptions(command, o.view, false);
  command.add_option("--field", o.wave.fieldDeg, "Field angle in degrees from the axis (object side)")
      ->capture_default_str()
      ->check(aNumber("degrees"));
  command.add_option(
      "--wavelengths", o.wavelengths,
      "Comma-separated wavelengths in nm, the first the primary (the reference sphere's centre); "
      "default: the d, F and C lines 587.56,486.13,656.27");
  command.add_option("--weights", o.weights, "Comma-separated weights, one per wavelength (default: equal)");
  command.add_option(
      "--pupil-samples", o.wave.pupilSamples,
      "Pupil grid points across the beam (odd, 9-2049); default 0: automatic, 65 doubled until the "
      "OPD changes by less than a quarter wave per sample");
  command.add_option("--padding", o.wave.padding, "FFT size over the pupil samples (2-32)")
      ->capture_default_str();
  command.add_option("--blades", o.wave.blades, "Aperture blades (0 round, else 3-64), as render --blades");
  command
      .add_option("--blade-rotation", o.wave.bladeRotationDeg,
                  "First blade corner's angle from lens-space +x, degrees")
      ->check(aNumber("degrees"));
  command.add_option("--aperture-mask", o.wave.apertureMask,
                     "A grey-scale image over the stop, as render --aperture-mask");
  addLensCoatingsOption(command, o.view.coatings, "as amplitude in the pupil");
  command.add_option("--csv", o.csv, "Write the plotted data as CSV, '-' for standard output");
  command.add_flag("--json", o.json, "Print the figures and the sampling as JSON on standard output");
}

int runLensWaveCommand(const LensWaveCommandOptions& options,
                       const std::function<LensPlot(const LensWave&, nlohmann::json&)>& make) {
  if (options.view.output.empty() && options.csv.empty() && !options.json)
    throw CLI::RequiredError("an output: -o FILE.svg, --csv FILE or --json");
  if (options.json && options.csv == "-")
    throw UsageError("--csv", "'-' and --json both want standard output");
  if (!options.view.output.empty() && std::filesystem::path(options.view.output).extension() == ".svg")
    noteCreatedFolder(createFolderFor(options.view.output), false);
  if (!options.csv.empty() && options.csv != "-") {
    noteCreatedFolder(createFolderFor(options.csv), false);
    checkOutputDirectory(options.csv);
  }
  LensWaveOptions wave = options.wave;
  if (!options.wavelengths.empty())
    wave.wavelengthsNm = parseNumberList(options.wavelengths, "--wavelengths");
  if (!options.weights.empty()) wave.weights = parseNumberList(options.weights, "--weights");
  Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
  const LensWave lensWave = prepareLensWave(options.view, wave, warnings);
  nlohmann::json json;
  const LensPlot plot = make(lensWave, json);
  if (!options.view.output.empty()) {
    plot.svg.write(options.view.output);
    fmt::print(stderr, "lensrt: wrote {}\n", options.view.output);
  }
  if (!options.csv.empty()) {
    writeTextOutput(options.csv, plot.table.csv());
    if (options.csv != "-") fmt::print(stderr, "lensrt: wrote {}\n", options.csv);
  }
  if (options.json) std::cout << json.dump(2) << "\n";
  return 0;
}

}  // namespace lensrt
