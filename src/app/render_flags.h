// The environment and scene-access flags of `lensrt render` and `lensrt
// compare` (the settings they fill are api/render_options.h's).
#pragma once

#include <CLI/CLI.hpp>

#include "api/render_options.h"

namespace lensrt {

void addEnvironmentOptions(CLI::App& command, EnvironmentArgs& args);
// --allow-external-files (or LENSRT_ALLOW_EXTERNAL_FILES=1) and --max-texture-memory MIB.
void addSceneAccessOptions(CLI::App& command, SceneAccessArgs& args);

}  // namespace lensrt
