// The sRGB transfer functions (IEC 61966-2-1), used for 8-bit previews.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lensrt {

// Linear [0,1] -> encoded [0,1]: a linear toe below 0.0031308, then a 1/2.4
// power; values outside [0,1] (and NaN) are clamped first.
inline float srgbEncode(float linear) {
  const float v = std::isnan(linear) ? 0.0f : std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// Encoded [0,1] -> linear [0,1], the inverse of srgbEncode.
inline float srgbDecode(float encoded) {
  const float v = std::clamp(encoded, 0.0f, 1.0f);
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

// Linear value -> 8-bit sRGB code, rounded to nearest.
inline std::uint8_t srgbEncode8(float linear) {
  return std::uint8_t(std::lround(srgbEncode(linear) * 255.0f));
}

}  // namespace lensrt
