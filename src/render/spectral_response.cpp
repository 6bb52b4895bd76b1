#include "render/spectral_response.h"

#include <array>
#include <cmath>
#include <vector>

#include "render/distribution.h"

namespace lensrt {

namespace {

struct Band {
  double centreNm, sigmaNm;
};
constexpr std::array<Band, 3> kBands{{{605.0, 32.0}, {535.0, 32.0}, {455.0, 28.0}}};  // R, G, B
constexpr int kTableBins = 400;                                                       // 1 nm

// Integral of exp(-(l - c)^2 / (2 s^2)) over the wavelength range.
double bandIntegral(const Band& b) {
  const double k = 1.0 / (b.sigmaNm * std::sqrt(2.0));
  return b.sigmaNm * std::sqrt(M_PI / 2.0) *
         (std::erf((kWavelengthMaxNm - b.centreNm) * k) - std::erf((kWavelengthMinNm - b.centreNm) * k));
}

// The sampling table over the mean response, built once (a constant).
struct Table {
  Distribution1D distribution;
  Table() {
    std::vector<float> w(kTableBins);
    for (int i = 0; i < kTableBins; ++i) {
      const Rgb r =
          spectralResponse(kWavelengthMinNm + (i + 0.5) * (kWavelengthMaxNm - kWavelengthMinNm) / kTableBins);
      w[i] = r.x + r.y + r.z;
    }
    distribution = Distribution1D(w);
  }
};

const Table& table() {
  static const Table t;
  return t;
}

}  // namespace

Rgb spectralResponse(double wavelengthNm) {
  if (!(wavelengthNm >= kWavelengthMinNm && wavelengthNm <= kWavelengthMaxNm)) return {0, 0, 0};
  static const std::array<double, 3> norm{1.0 / bandIntegral(kBands[0]), 1.0 / bandIntegral(kBands[1]),
                                          1.0 / bandIntegral(kBands[2])};
  std::array<float, 3> r{};
  for (int c = 0; c < 3; ++c) {
    const double t = (wavelengthNm - kBands[c].centreNm) / kBands[c].sigmaNm;
    r[c] = float(norm[c] * std::exp(-0.5 * t * t));
  }
  return {r[0], r[1], r[2]};
}

WavelengthSample sampleWavelength(float u) {
  const Distribution1D& d = table().distribution;
  float within = 0.0f;
  const std::size_t bin = d.sample(u, &within);
  constexpr double kBinNm = double(kWavelengthMaxNm - kWavelengthMinNm) / kTableBins;
  // The weights at the wavelength the camera gets (a float).
  const float wl = float(kWavelengthMinNm + (double(bin) + within) * kBinNm);
  const double pdf = double(d.probability(bin)) / kBinNm;  // per nm
  const Rgb r = spectralResponse(wl);
  return {wl, Rgb{float(r.x / pdf), float(r.y / pdf), float(r.z / pdf)}};
}

}  // namespace lensrt
