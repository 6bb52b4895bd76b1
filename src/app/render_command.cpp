// Placeholder until the render command lands; replaced by its owner.
#include "app/command.h"

namespace lensrt {

CommandAction addRenderCommand(CLI::App& app, const CommandContext&) {
  app.add_subcommand("render", "(not built yet)");
  return []() -> int { throw std::runtime_error("the render command is not built yet"); };
}

}  // namespace lensrt
