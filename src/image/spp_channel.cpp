#include "image/spp_channel.h"

#include <algorithm>
#include <cstdio>

namespace lensrt {

std::optional<std::string> adaptiveSppSummary(const Image& image) {
  const int c = image.channelIndex(kSppChannel);
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  if (c < 0 || pixels == 0) return std::nullopt;
  double sum = 0;
  float lo = image.pixels[std::size_t(c)], hi = lo;
  for (std::size_t i = 0; i < pixels; ++i) {
    const float v = image.pixels[i * image.channelCount() + std::size_t(c)];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
  }
  char text[96];
  std::snprintf(text, sizeof text, "adaptive min=%.0f mean=%.2f max=%.0f", double(lo), sum / double(pixels),
                double(hi));
  return std::string(text);
}

bool isAdaptiveSpp(const std::string& value) {
  return value.rfind("adaptive", 0) == 0;
}

}  // namespace lensrt
