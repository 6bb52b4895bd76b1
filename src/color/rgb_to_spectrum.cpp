#include "color/rgb_to_spectrum.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace lensrt {

// The generated table, linked in as bytes (rgb_to_spectrum_data.S): float32
// z nodes, then the coefficients, little-endian as the build machine wrote them.
extern "C" const unsigned char lensrt_rgb_to_spectrum_srgb[];
extern "C" const unsigned char lensrt_rgb_to_spectrum_srgb_end[];

float SigmoidPolynomial::maxValue() const {
  float m = std::max((*this)(360.0f), (*this)(830.0f));
  if (c0 != 0) {
    const float vertex = -c1 / (2 * c0);
    if (vertex >= 360.0f && vertex <= 830.0f) m = std::max(m, (*this)(vertex));
  }
  return m;
}

RgbToSpectrumTable::RgbToSpectrumTable(std::span<const float> zNodes, std::span<const float> coefficients)
    : zNodes_(zNodes), coefficients_(coefficients) {
  constexpr std::size_t r = kResolution;
  if (zNodes_.size() != r || coefficients_.size() != 3 * r * r * r * 3)
    throw std::invalid_argument("RGB-to-spectrum table of the wrong size");
}

const RgbToSpectrumTable& RgbToSpectrumTable::srgb() {
  static const RgbToSpectrumTable table = [] {
    constexpr std::size_t r = kResolution, floats = r + 3 * r * r * r * 3;
    const std::size_t bytes = std::size_t(lensrt_rgb_to_spectrum_srgb_end - lensrt_rgb_to_spectrum_srgb);
    if (bytes != floats * sizeof(float))
      throw std::logic_error("the linked RGB-to-spectrum table has the wrong size");
    // The bytes carry no alignment guarantee: the table reads them in place
    // only if they are aligned for float (the assembler aligns them to 16).
    if (reinterpret_cast<std::uintptr_t>(lensrt_rgb_to_spectrum_srgb) % alignof(float) != 0)
      throw std::logic_error("the linked RGB-to-spectrum table is not aligned");
    const auto* data = reinterpret_cast<const float*>(lensrt_rgb_to_spectrum_srgb);
    return RgbToSpectrumTable(std::span(data, r), std::span(data + r, floats - r));
  }();
  return table;
}

SigmoidPolynomial RgbToSpectrumTable::operator()(const Vec3f& rgbIn) const {
  const Vec3f rgb{std::clamp(rgbIn.x, 0.0f, 1.0f), std::clamp(rgbIn.y, 0.0f, 1.0f),
                  std::clamp(rgbIn.z, 0.0f, 1.0f)};
  // A grey is flat: sigmoid(c2) = value.
  if (rgb.x == rgb.y && rgb.y == rgb.z) {
    const float v = rgb.x;
    if (v <= 0) return {0, 0, -std::numeric_limits<float>::infinity()};
    if (v >= 1) return {0, 0, std::numeric_limits<float>::infinity()};
    return {0, 0, (v - 0.5f) / std::sqrt(v * (1 - v))};
  }
  constexpr int r = kResolution;
  const int m = rgb.x > rgb.y ? (rgb.x > rgb.z ? 0 : 2) : (rgb.y > rgb.z ? 1 : 2);
  const float z = rgb[std::size_t(m)];
  const float x = rgb[std::size_t((m + 1) % 3)] * float(r - 1) / z;
  const float y = rgb[std::size_t((m + 2) % 3)] * float(r - 1) / z;
  const int xi = std::min(int(x), r - 2), yi = std::min(int(y), r - 2);
  // The z interval: the last node below z.
  const int zi = int(std::clamp<std::ptrdiff_t>(
      std::upper_bound(zNodes_.begin(), zNodes_.end(), z) - zNodes_.begin() - 1, 0, r - 2));
  const float dx = x - float(xi), dy = y - float(yi);
  const float dz = (z - zNodes_[std::size_t(zi)]) / (zNodes_[std::size_t(zi) + 1] - zNodes_[std::size_t(zi)]);
  std::array<float, 3> c{};
  const auto at = [&](int k, int j, int i, int n) {
    return coefficients_
        [((((std::size_t(m) * r + std::size_t(k)) * r + std::size_t(j)) * r + std::size_t(i)) * 3) +
         std::size_t(n)];
  };
  for (int n = 0; n < 3; ++n) {
    const auto lerp = [](float t, float a, float b) { return a + t * (b - a); };
    c[std::size_t(n)] = lerp(dz,
                             lerp(dy, lerp(dx, at(zi, yi, xi, n), at(zi, yi, xi + 1, n)),
                                  lerp(dx, at(zi, yi + 1, xi, n), at(zi, yi + 1, xi + 1, n))),
                             lerp(dy, lerp(dx, at(zi + 1, yi, xi, n), at(zi + 1, yi, xi + 1, n)),
                                  lerp(dx, at(zi + 1, yi + 1, xi, n), at(zi + 1, yi + 1, xi + 1, n))));
  }
  return {c[0], c[1], c[2]};
}

}  // namespace lensrt
