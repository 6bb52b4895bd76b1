// The flags `lens diagram` and `lens plot` share (the settings they fill are
// api/lens_view.h's).
#pragma once

#include <CLI/CLI.hpp>

#include "api/lens_view.h"

namespace lensrt {

// Registers FILE, -o/--output, --fstop, --focus and --sensor; -o is
// required unless `outputRequired` is false (the command then has another
// output and checks that one of them is given).
void addLensViewOptions(CLI::App& command, LensViewOptions& options, bool outputRequired = true);

}  // namespace lensrt
