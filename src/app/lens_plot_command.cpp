// `lensrt lens plot FILE --what relative-illumination|distortion|spot
//  [-o out.svg] [--csv out.csv]`.
#include <fmt/core.h>

#include <memory>

#include "app/lens_plot.h"
#include "app/lens_plot_setup.h"
#include "app/lens_subcommands.h"
#include "app/text_file.h"

namespace lensrt {

CommandAction addLensPlotCommand(CLI::App& lensApp, const CommandContext&) {
  struct Options {
    LensViewOptions view;
    std::string what;
    std::string csv;
  };
  auto options = std::make_shared<Options>();
  CLI::App* plot = lensApp.add_subcommand(
      "plot", "Plot relative illumination, distortion or spot diagrams across the field (SVG and/or CSV)");
  addLensViewOptions(*plot, options->view, false);
  plot->add_option("--what", options->what, "relative-illumination, distortion or spot")
      ->required()
      ->check(CLI::IsMember({"relative-illumination", "distortion", "spot"}));
  plot->add_option("--csv", options->csv,
                   "Also (or instead of -o) write the plotted data as CSV, '-' for standard output: a header "
                   "naming the columns, then one row per plotted point (per ray for spot)");
  return [options] {
    if (options->view.output.empty() && options->csv.empty())
      throw CLI::RequiredError("an output: -o FILE.svg or --csv FILE (or both)");
    if (!options->csv.empty() && options->csv != "-") checkOutputDirectory(options->csv);
    Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
    const LensView view = prepareLensView(options->view, warnings);
    const LensPlot plot = options->what == "distortion" ? plotDistortion(view)
                          : options->what == "spot"     ? plotSpotDiagrams(view)
                                                        : plotRelativeIllumination(view);
    if (!options->view.output.empty()) plot.svg.write(options->view.output);
    if (!options->csv.empty()) writeTextOutput(options->csv, plot.table.csv());
    return 0;
  };
}

}  // namespace lensrt
