// RGB to smooth spectra (Jakob and Hanika 2019, "A Low-Dimensional Function
// Space for Efficient Spectral Upsampling"): a reflectance colour becomes
// s(l) = sigmoid(c0 l^2 + c1 l + c2), the smooth spectrum in [0, 1] whose
// colour under the space's illuminant (D65 for sRGB) is that colour. The
// coefficients come from a table over RGB made at build time by our own
// optimiser (rgb2spec_generate.cpp), as pbrt-v4 does with the paper's.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

#include "core/vec.h"

namespace lensrt {

struct SigmoidPolynomial {
  float c0 = 0, c1 = 0, c2 = 0;  // in nm

  float operator()(float nm) const {
    const float x = (c0 * nm + c1) * nm + c2;
    if (std::isinf(x)) return x > 0 ? 1.0f : 0.0f;
    return 0.5f + x / (2 * std::sqrt(1 + x * x));
  }
  // The largest value over 360-830 nm (at an end or at the vertex).
  float maxValue() const;
};

class RgbToSpectrumTable {
 public:
  static constexpr int kResolution = 64;
  // The table for linear sRGB (Rec. 709 primaries, D65).
  static const RgbToSpectrumTable& srgb();

  // rgb in [0, 1]^3 (values outside are clamped).
  SigmoidPolynomial operator()(const Vec3f& rgb) const;

  // The generator's layout: for the largest component m (0-2), its value z
  // (node k), and the other two over it, x = rgb[(m+1)%3] / z (node i) and
  // y = rgb[(m+2)%3] / z (node j): coefficients at
  // ((((m * R + k) * R + j) * R + i) * 3. z's nodes are spaced by
  // smoothstep(smoothstep(k / (R - 1))), denser near 0 and 1.
  RgbToSpectrumTable(std::span<const float> zNodes, std::span<const float> coefficients);

 private:
  std::span<const float> zNodes_, coefficients_;
};

// z node k of the table.
double rgbToSpectrumNode(int k, int resolution);

}  // namespace lensrt
