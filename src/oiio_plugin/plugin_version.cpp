// What the plugin is: the interface version it speaks and the libraries it
// runs on.
#include <OpenImageIO/color.h>
#include <OpenImageIO/imageio.h>

#include <string>

#include "image/oiio_plugin_abi.h"

extern "C" {

int lensrt_oiio_abi_version(void) {
  return LENSRT_OIIO_ABI_VERSION;
}

const char* lensrt_oiio_library_version(void) {
  static const std::string text = [] {
    // The library's own numbers at run time, not the headers'.
    const int v = OIIO::openimageio_version();
    // Appended piece by piece: GCC 12 misreads "literal" + std::string (bug 105329).
    const auto version = [](int major, int minor, int patch) {
      std::string t = std::to_string(major);
      t += '.';
      t += std::to_string(minor);
      t += '.';
      t += std::to_string(patch);
      return t;
    };
    std::string t = "OpenImageIO ";
    t += version(v / 10000, v / 100 % 100, v % 100);
    // OCIO_VERSION_HEX: major << 24 | minor << 16 | patch << 8.
    if (const int ocio = OIIO::ColorConfig::OpenColorIO_version_hex(); ocio != 0) {
      t += " (OpenColorIO ";
      t += version(ocio >> 24, (ocio >> 16) & 0xff, (ocio >> 8) & 0xff);
      t += ')';
    }
    return t;
  }();
  return text.c_str();
}

}  // extern "C"
