// `lensrt lens diagram FILE -o lens.svg [--ghost I,J]`: the lens drawn with
// ray fans, and optionally one ghost path.
#include <fmt/core.h>

#include <cstdlib>
#include <memory>
#include <optional>

#include "api/output_file.h"
#include "app/command.h"
#include "app/lens_subcommands.h"
#include "app/lens_view_flags.h"
#include "core/error.h"
#include "report/lens_diagram.h"

namespace lensrt {

namespace {

// --ghost I,J: surfaces numbered from the front, I (reflecting first) behind
// J, both where the index changes. Throws UsageError.
DiagramGhost parseGhost(const std::string& text, const LensPrescription& lens) {
  const std::size_t comma = text.find(',');
  char* end1 = nullptr;
  char* end2 = nullptr;
  const long i = comma == std::string::npos ? 0 : std::strtol(text.c_str(), &end1, 10);
  const long j = comma == std::string::npos ? 0 : std::strtol(text.c_str() + comma + 1, &end2, 10);
  if (comma == std::string::npos || comma == 0 || end1 != text.c_str() + comma ||
      end2 == text.c_str() + comma + 1 || *end2 != '\0')
    throw UsageError("--ghost",
                     "expected two surface numbers I,J (numbered from the front, I > J), got '" + text + "'");
  const long count = long(lens.surfaces.size());
  for (const long k : {i, j})
    if (k < 1 || k > count)
      throw UsageError("--ghost", fmt::format("surface {} is not one of the lens's {} surfaces", k, count));
  if (i <= j)
    throw UsageError("--ghost",
                     fmt::format("the light reflects first at the surface nearer the film: expected "
                                 "I > J, got {},{} (try {},{})",
                                 i, j, j, i));
  for (const long k : {i, j}) {
    const std::size_t s = std::size_t(k - 1);
    const double before = s > 0 ? lens.surfaces[s - 1].medium.nd : 1.0;
    if (lens.surfaces[s].isStop || before == lens.surfaces[s].medium.nd)
      throw UsageError("--ghost", fmt::format("surface {} reflects nothing ({})", k,
                                              lens.surfaces[s].isStop ? "it is the stop"
                                                                      : "the same index on both sides"));
  }
  return {int(i - 1), int(j - 1)};
}

}  // namespace

CommandAction addLensDiagramCommand(CLI::App& lensApp, const CommandContext&) {
  struct Options {
    LensViewOptions view;
    std::string ghost;
  };
  auto options = std::make_shared<Options>();
  CLI::App* diagram = lensApp.add_subcommand(
      "diagram", "Draw the lens to scale with ray fans, stop, pupils and cardinal points (SVG)");
  addLensViewOptions(*diagram, options->view);
  diagram->add_option(
      "--ghost", options->ghost,
      "Also draw the ghost I,J (see lens ghosts): an axial bundle reflected at surface I, then "
      "at J < I, numbered from the front");
  return [options] {
    Warnings warnings([](const std::string& w) { fmt::print(stderr, "lensrt: warning: {}\n", w); });
    if (std::filesystem::path(options->view.output).extension() == ".svg")
      noteCreatedFolder(createFolderFor(options->view.output), false);
    const LensView view = prepareLensView(options->view, warnings);
    std::optional<DiagramGhost> ghost;
    if (!options->ghost.empty()) ghost = parseGhost(options->ghost, view.lens.prescription());
    drawLensDiagram(view, ghost).write(options->view.output);
    fmt::print(stderr, "lensrt: wrote {}\n", options->view.output);
    return 0;
  };
}

}  // namespace lensrt
