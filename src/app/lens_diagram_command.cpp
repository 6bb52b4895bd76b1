// `lensrt lens diagram FILE -o lens.svg`: the lens drawn with ray fans.
#include <fmt/core.h>

#include <memory>

#include "api/output_file.h"
#include "app/command.h"
#include "app/lens_subcommands.h"
#include "app/lens_view_flags.h"
#include "report/lens_diagram.h"

namespace lensrt {

CommandAction addLensDiagramCommand(CLI::App& lensApp, const CommandContext&) {
  auto options = std::make_shared<LensViewOptions>();
  CLI::App* diagram = lensApp.add_subcommand(
      "diagram", "Draw the lens to scale with ray fans, stop, pupils and cardinal points (SVG)");
  addLensViewOptions(*diagram, *options);
  return [options] {
    Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
    if (std::filesystem::path(options->output).extension() == ".svg")
      noteCreatedFolder(createFolderFor(options->output), false);
    const LensView view = prepareLensView(*options, warnings);
    drawLensDiagram(view).write(options->output);
    fmt::print(stderr, "lensrt: wrote {}\n", options->output);
    return 0;
  };
}

}  // namespace lensrt
