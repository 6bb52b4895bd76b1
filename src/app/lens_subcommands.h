// `lensrt lens <sub>`: each sub-subcommand lives in its own file and
// registers on the `lens` subcommand, returning the action to run when it is
// chosen (see command.h). lens_command.cpp calls every hook listed here.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "app/command.h"

namespace lensrt {

// lens_command.cpp: the `--coatings none|single|multi` option of `lens info`
// and `lens ghosts`, `what` saying what the coatings change there.
void addLensCoatingsOption(CLI::App& cmd, std::string& coatings, const std::string& what);
// lens_command.cpp: `lens info FILE [--sensor WxH] [--fstop N] [--focus M] [--json]`.
CommandAction addLensInfoCommand(CLI::App& lens, const CommandContext& context);
// Hooks for later files (lens_diagram_command.cpp, lens_plot_command.cpp);
// add their calls to the table in lens_command.cpp when they land.
CommandAction addLensDiagramCommand(CLI::App& lens, const CommandContext& context);
CommandAction addLensPlotCommand(CLI::App& lens, const CommandContext& context);
// lens_ghosts_command.cpp: `lens ghosts LENS [--coatings X] [--json]`.
CommandAction addLensGhostsCommand(CLI::App& lens, const CommandContext& context);
// lens_calibrate_command.cpp: `lens calibrate LENS --res WxH --focus M|inf [--model ...] [--json]`.
CommandAction addLensCalibrateCommand(CLI::App& lens, const CommandContext& context);
// lens_psf_command.cpp, lens_mtf_command.cpp: `lens psf` and `lens mtf` (app/lens_wave_flags.h).
CommandAction addLensPsfCommand(CLI::App& lens, const CommandContext& context);
CommandAction addLensMtfCommand(CLI::App& lens, const CommandContext& context);

}  // namespace lensrt
