// The environment flags of `lensrt render` and `lensrt compare` (the
// settings they fill are api/render_options.h's).
#pragma once

#include <CLI/CLI.hpp>

#include "api/render_options.h"

namespace lensrt {

void addEnvironmentOptions(CLI::App& command, EnvironmentArgs& args);

}  // namespace lensrt
