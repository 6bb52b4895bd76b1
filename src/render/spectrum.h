// The colour a path carries: four lanes, operated on component-wise. Under
// spectral transport (render/wavelengths.h) the lanes are the radiance at a
// sample's four wavelengths; under RGB transport they are (R, G, B, G): the
// fourth lane repeats green, so every component-wise result, the largest
// component and the luminance are the bits RGB arithmetic gives, and the
// BSDFs and the integrator need one code path for both.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "core/vec.h"

namespace lensrt {

struct Spectrum {
  static constexpr std::size_t kLanes = 4;
  std::array<float, kLanes> v{};

  constexpr Spectrum() = default;
  // A constant over every lane (a grey, in either transport).
  constexpr explicit Spectrum(float c) : v{c, c, c, c} {}
  constexpr Spectrum(float a, float b, float c, float d) : v{a, b, c, d} {}
  // An RGB value under RGB transport (R, G, B, G). Explicit: under spectral
  // transport a colour becomes a Spectrum through SampledWavelengths alone.
  constexpr explicit Spectrum(const Rgb& c) : v{c.x, c.y, c.z, c.y} {}

  constexpr float operator[](std::size_t i) const { return v[i]; }
  constexpr float& operator[](std::size_t i) { return v[i]; }
  // Lanes 0-2: the RGB value under RGB transport.
  constexpr Rgb rgb() const { return {v[0], v[1], v[2]}; }

  constexpr Spectrum operator+(const Spectrum& b) const {
    return map(b, [](float x, float y) { return x + y; });
  }
  constexpr Spectrum operator-(const Spectrum& b) const {
    return map(b, [](float x, float y) { return x - y; });
  }
  constexpr Spectrum operator*(const Spectrum& b) const {
    return map(b, [](float x, float y) { return x * y; });
  }
  constexpr Spectrum operator/(const Spectrum& b) const {
    return map(b, [](float x, float y) { return x / y; });
  }
  constexpr Spectrum operator*(float s) const { return {v[0] * s, v[1] * s, v[2] * s, v[3] * s}; }
  constexpr Spectrum operator/(float s) const { return {v[0] / s, v[1] / s, v[2] / s, v[3] / s}; }
  constexpr Spectrum& operator+=(const Spectrum& b) { return *this = *this + b; }
  constexpr Spectrum& operator*=(const Spectrum& b) { return *this = *this * b; }
  constexpr Spectrum& operator*=(float s) { return *this = *this * s; }
  constexpr bool operator==(const Spectrum&) const = default;

 private:
  template <class F>
  constexpr Spectrum map(const Spectrum& b, F f) const {
    return {f(v[0], b.v[0]), f(v[1], b.v[1]), f(v[2], b.v[2]), f(v[3], b.v[3])};
  }
};

constexpr Spectrum operator*(float s, const Spectrum& c) {
  return c * s;
}
constexpr float maxComponent(const Spectrum& c) {
  const float a = c[0] > c[1] ? c[0] : c[1], b = c[2] > c[3] ? c[2] : c[3];
  return a > b ? a : b;
}
constexpr Spectrum min(const Spectrum& a, const Spectrum& b) {
  return {a[0] < b[0] ? a[0] : b[0], a[1] < b[1] ? a[1] : b[1], a[2] < b[2] ? a[2] : b[2],
          a[3] < b[3] ? a[3] : b[3]};
}
constexpr Spectrum max(const Spectrum& a, const Spectrum& b) {
  return {a[0] > b[0] ? a[0] : b[0], a[1] > b[1] ? a[1] : b[1], a[2] > b[2] ? a[2] : b[2],
          a[3] > b[3] ? a[3] : b[3]};
}
inline Spectrum exp(const Spectrum& c) {
  return {std::exp(c[0]), std::exp(c[1]), std::exp(c[2]), std::exp(c[3])};
}
inline bool isFinite(const Spectrum& c) {
  return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]);
}
// A weight for choosing between lobes (never a value that reaches the film):
// the Rec. 709 luminance of lanes 0-2, which under RGB transport is the
// luminance itself. Under spectral transport it weighs three of the four
// wavelengths; the upsampled spectra are positive at every wavelength
// wherever they are positive at one, so no lobe with a value gets weight 0.
constexpr float luminance(const Spectrum& c) {
  return luminance(c.rgb());
}

}  // namespace lensrt
