#include "render/pixel_region.h"

#include <stdexcept>

namespace lensrt {

std::string PixelRegion::describe() const {
  return std::to_string(x0) + "," + std::to_string(x1) + "," + std::to_string(y0) + "," + std::to_string(y1);
}

PixelRegion frameStrip(int index, int count, int width, int height) {
  if (count < 1 || index < 0 || index >= count || count > height)
    throw std::invalid_argument("tile " + std::to_string(index) + "/" + std::to_string(count) +
                                " does not exist for an image " + std::to_string(height) + " pixels high");
  const auto row = [&](int i) { return int(std::int64_t(i) * height / count); };
  return {0, width, row(index), row(index + 1)};
}

}  // namespace lensrt
