// Each subcommand of `lensrt` lives in its own file: it registers its options
// on the main CLI11 app and returns the action to run when it is chosen.
#pragma once

#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "api/output_file.h"

namespace lensrt {

class MpiJob;

struct CommandContext {
  std::string commandLine;     // the whole invocation, recorded in output metadata
  MpiJob* mpi = nullptr;  // the MPI job (owned by main), never null once main runs
};

// Returns the process exit status. Bad input is reported by throwing
// InputError; main() prints it as one line and exits 1.
using CommandAction = std::function<int()>;

CommandAction addRenderCommand(CLI::App& app, const CommandContext& context);
CommandAction addLensCommand(CLI::App& app, const CommandContext& context);
CommandAction addDiffCommand(CLI::App& app, const CommandContext& context);
CommandAction addCompareCommand(CLI::App& app, const CommandContext& context);
CommandAction addMergeCommand(CLI::App& app, const CommandContext& context);
CommandAction addSensorCommand(CLI::App& app, const CommandContext& context);
CommandAction addOptionsCommand(CLI::App& app, const CommandContext& context);

}  // namespace lensrt
