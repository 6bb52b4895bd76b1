// OpenColorIO's display transforms, through OpenImageIO's ColorConfig of
// the $OCIO config (OpenImageIO's built-in fallback has no displays).
#include <OpenImageIO/color.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "image/oiio_plugin_abi.h"
#include "oiio_plugin/plugin_call.h"

namespace lensrt::oiio {
namespace {

// Read once: a config is expensive to build. Not const: reading its error
// text clears it.
OIIO::ColorConfig& config() {
  static OIIO::ColorConfig c;
  return c;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) {
    if (!text.empty()) text += ", ";
    text += n;
  }
  return text;
}

int transform(float* rgb, std::size_t pixelCount, const std::string& wantedDisplay,
              const std::string& wantedView) {
  if (!OIIO::ColorConfig::supportsOpenColorIO())
    throw Failure("this OpenImageIO was built without OpenColorIO");
  OIIO::ColorConfig& c = config();
  if (c.getNumDisplays() == 0) throw Failure("the OpenColorIO config has no displays");
  const std::string display = wantedDisplay.empty() ? c.getDefaultDisplayName() : wantedDisplay;
  if (!contains(c.getDisplayNames(), display))
    throw Failure(std::string("the OpenColorIO config has no display '") + display + "'");
  const std::string view = wantedView.empty() ? c.getDefaultViewName(display) : wantedView;
  if (!contains(c.getViewNames(display), view))
    throw Failure(std::string("display '") + display + "' has no view '" + view + "'");
  const char* sceneLinear = c.getColorSpaceNameByRole("scene_linear");
  const OIIO::ColorProcessorHandle processor =
      c.createDisplayTransform(display, view, sceneLinear ? sceneLinear : "linear");
  if (!processor) throw Failure(oneLine(c.geterror(), "OpenColorIO cannot make that display transform"));
  // In rows of at most 2^20 pixels: apply() counts pixels in an int.
  constexpr std::size_t kRow = std::size_t(1) << 20;
  for (std::size_t at = 0; at < pixelCount; at += kRow) {
    const int n = int(std::min(kRow, pixelCount - at));
    processor->apply(rgb + 3 * at, n, 1, 3, sizeof(float), 3 * sizeof(float),
                     OIIO::stride_t(n) * 3 * sizeof(float));
  }
  return LENSRT_OIIO_OK;
}

}  // namespace
}  // namespace lensrt::oiio

using namespace lensrt::oiio;

extern "C" {

int lensrt_oiio_display_transform(float* rgb, size_t pixel_count, const char* display, const char* view) {
  return guarded([&] { return transform(rgb, pixel_count, display ? display : "", view ? view : ""); });
}

int lensrt_oiio_displays(char** text) {
  return guarded([&] {
    std::string list;
    if (OIIO::ColorConfig::supportsOpenColorIO())
      for (const std::string& display : config().getDisplayNames()) {
        if (!list.empty()) list += "; ";
        list += display;
        list += ": ";
        list += joined(config().getViewNames(display));
      }
    *text = static_cast<char*>(std::malloc(list.size() + 1));
    if (!*text) throw std::bad_alloc();
    std::memcpy(*text, list.c_str(), list.size() + 1);
    return LENSRT_OIIO_OK;
  });
}

}  // extern "C"
