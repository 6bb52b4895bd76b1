#include "sensor/camera_rgb.h"

#include <tbb/parallel_for.h>

#include <stdexcept>

namespace lensrt {

void transformRgb(Image& image, const Mat3d& m) {
  const int first = image.channelIndex("R");
  if (first < 0 || image.channelIndex("G") != first + 1 || image.channelIndex("B") != first + 2)
    throw std::invalid_argument("a colour transform needs R, G, B channels side by side");
  const std::size_t count = image.channelCount();
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  tbb::parallel_for(std::size_t(0), pixels, [&](std::size_t p) {
    float* rgb = &image.pixels[p * count + std::size_t(first)];
    const Vec3d out = m * Vec3d{rgb[0], rgb[1], rgb[2]};
    rgb[0] = float(out.x), rgb[1] = float(out.y), rgb[2] = float(out.z);
  });
}

}  // namespace lensrt
