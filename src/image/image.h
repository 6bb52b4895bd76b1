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
  // Where these pixels sit in a larger frame (OpenEXR's data window inside
  // the display window): a crop or tile of a render. 0 sizes: the image is
  // the whole frame.
  int originX = 0;
  int originY = 0;
  int frameWidth = 0;
  int frameHeight = 0;

  Image() = default;
  Image(int w, int h, std::vector<std::string> names)
      : width(w), height(h), channels(std::move(names)), pixels(std::size_t(w) * h * channels.size(), 0.0f) {}

  std::size_t channelCount() const { return channels.size(); }
  int fullWidth() const { return frameWidth > 0 ? frameWidth : width; }
  int fullHeight() const { return frameHeight > 0 ? frameHeight : height; }
  bool isWholeFrame() const {
    return originX == 0 && originY == 0 && fullWidth() == width && fullHeight() == height;
  }
  int channelIndex(const std::string& name) const;  // -1 when absent
  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels.size() + c]; }
  float at(int x, int y, int c) const { return pixels[(std::size_t(y) * width + x) * channels.size() + c]; }
};

// String attributes stored in the file's header (EXR) as "lensrt:key" etc.
using ImageMetadata = std::map<std::string, std::string>;

}  // namespace lensrt
