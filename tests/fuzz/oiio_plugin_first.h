// For the fuzz targets whose inputs may go through the OpenImageIO plugin
// (fuzz_image, fuzz_gltf): libFuzzer ends with exit(), where LeakSanitizer's
// check would race the plugin's libraries joining their threads
// (core/leak_check.h). Loading the plugin before the first input and then
// registering the check with atexit makes the check run first, while those
// threads are idle: atexit handlers and static destructors run in reverse
// order of registration.
#pragma once

#include <cstdlib>
#include <string>

#include "core/leak_check.h"
#include "image/oiio_plugin.h"

namespace lensrt::fuzz {

inline void loadOiioPluginFirst() {
  std::string problem;  // without a plugin those inputs are InputErrors: nothing to load
  OiioPlugin::find(problem);
  std::atexit([] { checkLeaksBeforeExit(); });
}

}  // namespace lensrt::fuzz
