// The camera flags of `lensrt render` and `lensrt compare` (the settings
// they fill are api/camera_options.h's).
#pragma once

#include <CLI/CLI.hpp>

#include "api/camera_options.h"

namespace lensrt {

void addCameraOptions(CLI::App& command, CameraOptions& options);

}  // namespace lensrt
