#include "image/preview_values.h"

#include <algorithm>
#include <cmath>

#include "image/oiio_plugin.h"
#include "image/srgb.h"

namespace lensrt {

std::vector<float> previewValues(const std::filesystem::path& file, const Image& image,
                                 const std::vector<int>& rgb,
                                 const std::optional<DisplayTransform>& display) {
  const std::size_t pixelCount = std::size_t(image.width) * std::size_t(image.height);
  std::vector<float> values(pixelCount * 3);
  for (std::size_t i = 0; i < pixelCount; ++i)
    for (std::size_t c = 0; c < 3; ++c)
      values[i * 3 + c] = image.pixels[i * image.channelCount() + std::size_t(rgb[c])];
  if (!display) {
    for (float& v : values) v = srgbEncode(v);
    return values;
  }
  const OiioPlugin& plugin = OiioPlugin::get(file.string(), "an OpenColorIO display transform");
  plugin.displayTransform("--ocio-display", values, display->display, display->view);
  for (float& v : values) v = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
  return values;
}

}  // namespace lensrt
