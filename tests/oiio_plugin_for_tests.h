// Tests that read or write through lensrt's OpenImageIO plugin in their own
// process point its search at the plugin this build made, whatever directory
// they run from (the lensrt command finds it beside itself).
#pragma once

#include <cstdlib>
#include <string_view>

namespace lensrt::test {

// False when the build made none (built without OpenImageIO): tests of the
// formats it serves skip then.
inline bool builtOiioPlugin() {
  return !std::string_view(LENSRT_OIIO_PLUGIN_FILE).empty();
}

// Call before the process first needs the plugin; false when the build has
// none: skip the test then.
inline bool useBuiltOiioPlugin() {
  if (!builtOiioPlugin()) return false;
  ::setenv("LENSRT_OIIO_PLUGIN", LENSRT_OIIO_PLUGIN_FILE, 1);
  return true;
}

}  // namespace lensrt::test
