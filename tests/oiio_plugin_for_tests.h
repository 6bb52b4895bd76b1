// Tests that read or write through lensrt's OpenImageIO plugin in their own
// process point its search at the plugin this build made, whatever directory
// they run from (the lensrt command finds it beside itself).
#pragma once

#include <cstdlib>
#include <string_view>

namespace lensrt::test {

// Call before the process first needs the plugin; false when the build has
// none (built without OpenImageIO): skip the test then.
inline bool useBuiltOiioPlugin() {
  if (std::string_view(LENSRT_OIIO_PLUGIN_FILE).empty()) return false;
  ::setenv("LENSRT_OIIO_PLUGIN", LENSRT_OIIO_PLUGIN_FILE, 1);
  return true;
}

}  // namespace lensrt::test
