// `lensrt lens plot FILE --what relative-illumination|distortion|spot|chromatic
//  [-o out.svg] [--csv out.csv]`.
#include <fmt/core.h>

#include <memory>

#include "api/output_file.h"
#include "api/text_file.h"
#include "app/command.h"
#include "app/lens_subcommands.h"
#include "app/lens_view_flags.h"
#include "optics/chromatic.h"
#include "report/lens_plot.h"

namespace lensrt {

CommandAction addLensPlotCommand(CLI::App& lensApp, const CommandContext&) {
  struct Options {
    LensViewOptions view;
    std::string what;
    std::string csv;
  };
  auto options = std::make_shared<Options>();
  CLI::App* plot = lensApp.add_subcommand(
      "plot",
      "Plot relative illumination, distortion, spot diagrams or chromatic aberration (SVG and/or CSV)");
  addLensViewOptions(*plot, options->view, false);
  plot->add_option("--what", options->what, "relative-illumination, distortion, spot or chromatic")
      ->required()
      ->check(CLI::IsMember({"relative-illumination", "distortion", "spot", "chromatic"}));
  plot->add_option(
          "--coatings", options->view.coatings,
          "relative-illumination with the Fresnel losses of uncoated (none), single-layer (single) or "
          "multi-layer (multi) coated surfaces; default: lossless glass")
      ->check(CLI::IsMember({"none", "single", "multi"}));
  plot->add_option("--csv", options->csv,
                   "Also (or instead of -o) write the plotted data as CSV, '-' for standard output: a header "
                   "naming the columns, then one row per plotted point (per ray for spot)");
  return [options] {
    if (options->view.output.empty() && options->csv.empty())
      throw CLI::RequiredError("an output: -o FILE.svg or --csv FILE (or both)");
    if (!options->view.output.empty() && std::filesystem::path(options->view.output).extension() == ".svg")
      noteCreatedFolder(createFolderFor(options->view.output), false);
    if (!options->csv.empty() && options->csv != "-") {
      noteCreatedFolder(createFolderFor(options->csv), false);
      checkOutputDirectory(options->csv);
    }
    Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
    const LensView view = prepareLensView(options->view, warnings);
    if (options->what == "chromatic" && !hasDispersion(view.lens.prescription()))
      warnings.warn(view.lens.prescription().name +
                    ": no dispersion data (Abbe numbers or Sellmeier coefficients), so every wavelength "
                    "focuses alike: the chromatic curves are zero");
    const LensPlot plot = options->what == "distortion"  ? plotDistortion(view)
                          : options->what == "spot"      ? plotSpotDiagrams(view)
                          : options->what == "chromatic" ? plotChromatic(view)
                                                         : plotRelativeIllumination(view);
    if (!options->view.output.empty()) {
      plot.svg.write(options->view.output);
      fmt::print(stderr, "lensrt: wrote {}\n", options->view.output);
    }
    if (!options->csv.empty()) {
      writeTextOutput(options->csv, plot.table.csv());
      if (options->csv != "-") fmt::print(stderr, "lensrt: wrote {}\n", options->csv);
    }
    return 0;
  };
}

}  // namespace lensrt
