#include "camera/aperture_mask.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace lensrt {

ApertureMask::ApertureMask(int width, int height, std::vector<float> transmittance, std::string name)
    : width_(width), height_(height), values_(std::move(transmittance)), name_(std::move(name)) {
  if (width <= 0 || height <= 0) throw std::invalid_argument("the mask image is empty");
  if (values_.size() != std::size_t(width) * std::size_t(height))
    throw std::invalid_argument("the mask has the wrong number of values");
  bool any = false;
  // FNV-1a over the values' bits: stable across machines (IEEE floats).
  std::uint64_t h = 1469598103934665603ull;
  for (const float v : values_) {
    if (!(v >= 0.0f && v <= 1.0f)) throw std::invalid_argument("mask values must lie in [0, 1]");
    any = any || v > 0.0f;
    std::uint32_t bits = 0;
    std::memcpy(&bits, &v, sizeof bits);
    for (int b = 0; b < 4; ++b) h = (h ^ ((bits >> (8 * b)) & 0xffu)) * 1099511628211ull;
  }
  if (!any || meanOverDisk() <= 0.0) throw std::invalid_argument("the mask is black over the whole stop");
  digest_ = h;
}

double ApertureMask::transmittance(const Vec2d& p, double stopRadius) const {
  // One texel size for both axes: the longer side spans the diameter.
  const double texel = 2.0 * stopRadius / std::max(width_, height_);
  const double col = p.x / texel + 0.5 * width_, row = 0.5 * height_ - p.y / texel;
  if (!(col >= 0.0 && row >= 0.0 && col < width_ && row < height_)) return 0.0;
  return values_[std::size_t(row) * std::size_t(width_) + std::size_t(col)];
}

double ApertureMask::meanOverDisk() const {
  // In units of the stop radius: texel centres inside the unit disk.
  const double texel = 2.0 / std::max(width_, height_);
  double sum = 0.0;
  long inside = 0;
  for (int r = 0; r < height_; ++r)
    for (int c = 0; c < width_; ++c) {
      const double x = (c + 0.5 - 0.5 * width_) * texel, y = (0.5 * height_ - r - 0.5) * texel;
      if (x * x + y * y > 1.0) continue;
      sum += values_[std::size_t(r) * std::size_t(width_) + std::size_t(c)];
      ++inside;
    }
  return inside ? sum / double(inside) : 0.0;
}

std::string ApertureMask::describe() const {
  char buf[64];
  std::snprintf(buf, sizeof buf, " %dx%d #%016llx", width_, height_,
                static_cast<unsigned long long>(digest_));
  return name_ + buf;
}

}  // namespace lensrt
