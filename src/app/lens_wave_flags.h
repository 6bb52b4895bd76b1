// The flags `lens psf` and `lens mtf` share, and how they run: the lens and
// field (api/lens_wave.h), the outputs (-o SVG, --csv, --json).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "api/lens_wave.h"
#include "report/lens_plot.h"

namespace lensrt {

struct LensWaveCommandOptions {
  LensViewOptions view;
  LensWaveOptions wave;
  std::string wavelengths, weights;  // comma-separated, parsed when run
  std::string csv;
  bool json = false;
};

void addLensWaveOptions(CLI::App& command, LensWaveCommandOptions& options);

// Checks the outputs, prepares the lens and field, makes the plot and its
// JSON with `make`, and writes what was asked for; exit status 0.
int runLensWaveCommand(const LensWaveCommandOptions& options,
                       const std::function<LensPlot(const LensWave&, nlohmann::json&)>& make);

}  // namespace lensrt
