// A float image with named channels, the currency of the image layer.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace lensrt {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;  // e.g. R,G,B,A then AOVs such as depth.Z, variance.R
  std::vector<float> pixels;          // interleaved, row-major, row 0 at the top

  Image() = default;
  Image(int w, int h, std::vector<std::string> names)
      : width(w), height(h), channels(std::move(names)), pixels(std::size_t(w) * h * channels.size(), 0.0f) {}

  std::size_t channelCount() const { return channels.size(); }
  int channelIndex(const std::string& name) const;  // -1 when absent
  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels.size() + c]; }
  float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels.size() + c]; }
};

// String attributes stored in the file's header (EXR) as "lensrt:key" etc.
using ImageMetadata = std::map<std::string, std::string>;

}  // namespace lensrt
