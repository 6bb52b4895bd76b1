// Placeholder until the diff command lands; replaced by its owner.
#include "app/command.h"

namespace lensrt {

CommandAction addDiffCommand(CLI::App& app, const CommandContext&) {
  app.add_subcommand("diff", "(not built yet)");
  return []() -> int { throw std::runtime_error("the diff command is not built yet"); };
}

}  // namespace lensrt
