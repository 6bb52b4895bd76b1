// Build-time generator of the RGB-to-spectrum table (rgb_to_spectrum.h),
// written from Jakob and Hanika 2019, section 3: for each RGB node, the
// coefficients (c0, c1, c2) of s(l) = sigmoid(c0 t^2 + c1 t + c2), t the
// wavelength scaled to [0, 1] over 360-830 nm, that minimise the CIELAB
// distance between the target colour and the colour of s under the colour
// space's illuminant, found by Gauss-Newton starting from the neighbouring
// node's solution (walking away from a mid-range start, where the fit is
// easy, toward the saturated ends). Integrals use Simpson's 3/8 rule on a
// grid three times finer than 5 nm.
//
// Usage: rgb2spec_generate OUT.bin — writes the z nodes then the
// coefficients as float32 (the layout in rgb_to_spectrum.h).
// The result must not depend on the machine: no threads decide an order,
// and only +, *, /, sqrt and cbrt are used (libm's cbrt has no CPU-specific
// variants; the build compiles this file without FMA contraction).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "color/cie.h"
#include "color/color_space.h"
#include "color/illuminant.h"
#include "color/rgb_to_spectrum.h"

namespace lensrt {
namespace {

constexpr int kFine = (95 - 1) * 3 + 1;  // 5 nm segments, 3 sub-steps each
constexpr double kMinNm = 360, kMaxNm = 830;

struct Tables {
  std::array<double, kFine> t{};                   // wavelength scaled to [0, 1]
  std::array<std::array<double, kFine>, 3> rgb{};  // the RGB weight of each grid point
  Mat3d rgbToXyz, xyzToRgb;
  Vec3d white;  // XYZ of the illuminant (Y = 1)
};

Tables makeTables() {
  Tables tb;
  const ColorSpace& srgb = colorSpace(ColorSpaceId::Srgb);
  tb.rgbToXyz = srgb.rgbToXyz;
  tb.xyzToRgb = srgb.xyzToRgb;
  const double h = (kMaxNm - kMinNm) / (kFine - 1);
  std::array<double, kFine> weight{};
  double y = 0;
  for (int i = 0; i < kFine; ++i) {
    // Simpson's 3/8: 1, 3, 3, 2, 3, 3, 2, ..., 3, 3, 1 times 3h/8.
    double w = 3.0 / 8.0 * h;
    if (i != 0 && i != kFine - 1) w *= (i % 3 == 0) ? 2.0 : 3.0;
    weight[std::size_t(i)] = w;
    y += cieXyzMatching(kMinNm + i * h).y * d65(kMinNm + i * h) * w;
  }
  tb.white = {0, 0, 0};
  for (int i = 0; i < kFine; ++i) {
    const double nm = kMinNm + i * h;
    const double illuminant = d65(nm) / y;  // Y of the white = 1
    const Vec3d xyz = cieXyzMatching(nm) * (illuminant * weight[std::size_t(i)]);
    const Vec3d rgb = tb.xyzToRgb * xyz;
    tb.t[std::size_t(i)] = (nm - kMinNm) / (kMaxNm - kMinNm);
    for (std::size_t k = 0; k < 3; ++k) tb.rgb[k][std::size_t(i)] = rgb[k];
    tb.white += xyz;
  }
  return tb;
}

Vec3d lab(const Tables& tb, const Vec3d& rgb) {
  const Vec3d xyz = tb.rgbToXyz * rgb;
  const auto f = [](double v) {
    constexpr double d = 6.0 / 29.0;
    return v > d * d * d ? std::cbrt(v) : v / (3 * d * d) + 4.0 / 29.0;
  };
  const double fy = f(xyz.y / tb.white.y);
  return {116 * fy - 16, 500 * (f(xyz.x / tb.white.x) - fy), 200 * (fy - f(xyz.z / tb.white.z))};
}

double sigmoid(double x) {
  return 0.5 * x / std::sqrt(1 + x * x) + 0.5;
}

// The target's Lab minus the spectrum's.
Vec3d residual(const Tables& tb, const Vec3d& c, const Vec3d& targetLab) {
  Vec3d rgb{0, 0, 0};
  for (std::size_t i = 0; i < std::size_t(kFine); ++i) {
    const double t = tb.t[i];
    const double s = sigmoid((c.x * t + c.y) * t + c.z);
    rgb += Vec3d{tb.rgb[0][i], tb.rgb[1][i], tb.rgb[2][i]} * s;
  }
  return targetLab - lab(tb, rgb);
}

void gaussNewton(const Tables& tb, const Vec3d& target, Vec3d& c) {
  const Vec3d targetLab = lab(tb, target);
  for (int iteration = 0; iteration < 15; ++iteration) {
    const Vec3d r = residual(tb, c, targetLab);
    if (dot(r, r) < 1e-6) break;
    // Central differences for the Jacobian, one column per coefficient.
    constexpr double eps = 1e-4;
    std::array<Vec3d, 3> column;
    for (std::size_t k = 0; k < 3; ++k) {
      Vec3d lo = c, hi = c;
      lo[k] -= eps;
      hi[k] += eps;
      column[k] = (residual(tb, hi, targetLab) - residual(tb, lo, targetLab)) / (2 * eps);
    }
    const std::optional<Mat3d> inverse = Mat3d::columns(column[0], column[1], column[2]).inverse();
    if (!inverse) break;
    c -= *inverse * r;
    // Keep the polynomial bounded (a saturated colour pushes it to infinity).
    const double m = std::max({c.x, c.y, c.z});
    if (m > 200) c *= 200 / m;
  }
}

}  // namespace
}  // namespace lensrt

int main(int argc, char** argv) {
  using namespace lensrt;
  if (argc != 2) {
    std::fprintf(stderr, "usage: rgb2spec_generate OUT.bin\n");
    return 2;
  }
  constexpr int r = RgbToSpectrumTable::kResolution;
  const Tables tb = makeTables();
  std::vector<float> out(std::size_t(r) + std::size_t(3 * r * r * r * 3));
  for (int k = 0; k < r; ++k) out[std::size_t(k)] = float(rgbToSpectrumNode(k, r));
  float* coefficients = out.data() + r;
  // Each (largest component, y node) row is independent of the others.
  tbb::parallel_for(0, 3 * r, [&](int row) {
    const int m = row / r, j = row % r;
    const double y = j / double(r - 1);
    for (int i = 0; i < r; ++i) {
      const double x = i / double(r - 1);
      const auto solve = [&](int k, Vec3d& c) {
        const double z = rgbToSpectrumNode(k, r);
        Vec3d rgb;
        rgb[std::size_t(m)] = z;
        rgb[std::size_t((m + 1) % 3)] = x * z;
        rgb[std::size_t((m + 2) % 3)] = y * z;
        gaussNewton(tb, rgb, c);
        // From t in [0, 1] to nm: t = (l - 360) / 470.
        constexpr double c0 = kMinNm, c1 = 1.0 / (kMaxNm - kMinNm);
        float* o = coefficients +
                   ((((std::size_t(m) * r + std::size_t(k)) * r + std::size_t(j)) * r + std::size_t(i)) * 3);
        o[0] = float(c.x * c1 * c1);
        o[1] = float(c.y * c1 - 2 * c.x * c0 * c1 * c1);
        o[2] = float(c.z - c.y * c0 * c1 + c.x * c0 * c0 * c1 * c1);
      };
      const int start = r / 5;
      Vec3d c{0, 0, 0};
      for (int k = start; k < r; ++k) solve(k, c);
      c = {0, 0, 0};
      for (int k = start; k >= 0; --k) solve(k, c);
    }
  });
  std::FILE* f = std::fopen(argv[1], "wb");
  if (!f || std::fwrite(out.data(), sizeof(float), out.size(), f) != out.size() || std::fclose(f) != 0) {
    std::fprintf(stderr, "rgb2spec_generate: cannot write %s\n", argv[1]);
    return 1;
  }
  return 0;
}
