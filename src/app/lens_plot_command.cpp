// `lensrt lens plot FILE --what relative-illumination|distortion|spot -o out.svg`.
#include <fmt/core.h>

#include <memory>

#include "app/lens_plot.h"
#include "app/lens_plot_setup.h"
#include "app/lens_subcommands.h"

namespace lensrt {

CommandAction addLensPlotCommand(CLI::App& lensApp, const CommandContext&) {
  struct Options {
    LensViewOptions view;
    std::string what;
  };
  auto options = std::make_shared<Options>();
  CLI::App* plot = lensApp.add_subcommand(
      "plot", "Plot relative illumination, distortion or spot diagrams across the field (SVG)");
  addLensViewOptions(*plot, options->view);
  plot->add_option("--what", options->what, "relative-illumination, distortion or spot")
      ->required()
      ->check(CLI::IsMember({"relative-illumination", "distortion", "spot"}));
  return [options] {
    Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
    const LensView view = prepareLensView(options->view, warnings);
    const Svg svg = options->what == "distortion" ? plotDistortion(view)
                    : options->what == "spot"     ? plotSpotDiagrams(view)
                                                  : plotRelativeIllumination(view);
    svg.write(options->view.output);
    return 0;
  };
}

}  // namespace lensrt
