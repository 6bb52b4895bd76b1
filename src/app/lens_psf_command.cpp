// `lensrt lens psf LENS [--field DEG] [--wavelengths ...] [-o psf.svg]
//  [--csv FILE] [--json]`: the PSF by FFT of the pupil function.
#include <fmt/core.h>

#include <memory>

#include "app/lens_subcommands.h"
#include "app/lens_wave_flags.h"
#include "report/lens_wave_plot.h"

namespace lensrt {

CommandAction addLensPsfCommand(CLI::App& lensApp, const CommandContext&) {
  auto options = std::make_shared<LensWaveCommandOptions>();
  CLI::App* psf = lensApp.add_subcommand(
      "psf",
      "The point spread function of a field point by FFT of the pupil function (SVG, CSV and/or JSON)");
  addLensWaveOptions(*psf, *options);
  return [options] {
    return runLensWaveCommand(*options, [](const LensWave& wave, nlohmann::json& json) {
      const Psf psf = wave.model->psf();
      fmt::print(stderr, "lensrt: {}\n", samplingText(psf));
      json = psfSummaryJson(wave, psf);
      return plotPsf(wave, psf);
    });
  };
}

}  // namespace lensrt
