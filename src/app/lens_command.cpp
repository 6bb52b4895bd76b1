// Placeholder until the lens command lands; replaced by its owner.
#include "app/command.h"

namespace lensrt {

CommandAction addLensCommand(CLI::App& app, const CommandContext&) {
  app.add_subcommand("lens", "(not built yet)");
  return []() -> int { throw std::runtime_error("the lens command is not built yet"); };
}

}  // namespace lensrt
