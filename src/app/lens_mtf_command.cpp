// `lensrt lens mtf LENS [--field DEG] [--max-frequency F] [--focus-frequency F]
//  [--focus-range MM] [-o mtf.svg] [--csv FILE] [--json]`: the MTF
// (tangential, sagittal, the diffraction limit) and through focus.
#include <fmt/core.h>

#include <cmath>
#include <memory>

#include "app/lens_subcommands.h"
#include "app/lens_wave_flags.h"
#include "app/option_checks.h"
#include "report/lens_wave_plot.h"

namespace lensrt {

CommandAction addLensMtfCommand(CLI::App& lensApp, const CommandContext&) {
  struct Options {
    LensWaveCommandOptions common;
    std::optional<double> maxFrequency, focusFrequency, focusRangeMm;
  };
  auto options = std::make_shared<Options>();
  CLI::App* mtf = lensApp.add_subcommand(
      "mtf",
      "The MTF of a field point (tangential, sagittal, diffraction limit, through focus; SVG, CSV, JSON)");
  addLensWaveOptions(*mtf, options->common);
  mtf->add_option("--max-frequency", options->maxFrequency,
                  "Plot up to this frequency, cycles/mm (default: the cutoff)")
      ->check(aNumber("cycles/mm"));
  mtf->add_option("--focus-frequency", options->focusFrequency,
                  "The through-focus curve's frequency, cycles/mm (default: a quarter of the cutoff)")
      ->check(aNumber("cycles/mm"));
  mtf->add_option(
         "--focus-range", options->focusRangeMm,
         "The through-focus curve's film shifts, +-mm (default: 4 lambda N^2 at the primary wavelength)")
      ->check(aNumber("mm"));
  return [options] {
    for (const auto& [value, flag] : {std::pair{options->maxFrequency, "--max-frequency"},
                                      std::pair{options->focusFrequency, "--focus-frequency"},
                                      std::pair{options->focusRangeMm, "--focus-range"}})
      if (value && !(*value > 0.0 && *value < 1e5))
        throw UsageError(flag, "must be positive (and below 1e5)");
    return runLensWaveCommand(options->common, [&o = *options](const LensWave& wave, nlohmann::json& json) {
      const Psf psf = wave.model->psf();
      fmt::print(stderr, "lensrt: {}\n", samplingText(psf));
      const double cutoff = std::max(psf.cutoffPerMm.x, psf.cutoffPerMm.y);
      const MtfCurves curves = mtfCurves(psf, o.maxFrequency.value_or(cutoff), 101);
      const double primary = wave.model->settings().wavelengthsNm.front() * 1e-6;
      const double range = o.focusRangeMm.value_or(4.0 * primary * wave.fNumber * wave.fNumber);
      std::vector<double> shifts;
      for (int k = 0; k <= 20; ++k) shifts.push_back(range * (k / 10.0 - 1.0));
      const ThroughFocusMtf focus =
          throughFocusMtf(*wave.model, o.focusFrequency.value_or(cutoff / 4.0), shifts);
      json = psfSummaryJson(wave, psf);
      json["mtf"] = {{"frequency_per_mm", curves.frequencyPerMm},
                     {"tangential", curves.tangential},
                     {"sagittal", curves.sagittal},
                     {"limit_tangential", curves.limitTangential},
                     {"limit_sagittal", curves.limitSagittal}};
      json["through_focus"] = {{"frequency_per_mm", focus.frequencyPerMm},
                               {"film_shift_mm", focus.filmShiftMm},
                               {"tangential", focus.tangential},
                               {"sagittal", focus.sagittal},
                               {"limit", focus.limit}};
      return plotMtf(wave, psf, curves, focus);
    });
  };
}

}  // namespace lensrt
