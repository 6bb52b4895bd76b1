// Kodak's Cineon printing-density log encoding, as 10-bit DPX files store
// scanned film: 0.002 density per code value, a negative gamma of 0.6,
// reference black at code 95 and reference white at 685 (linear 0 and 1),
// so codes up to 1023 keep highlights up to 13.5 times white. The same curve
// as OpenColorIO's "Cineon" / "lg10" colour spaces.
#pragma once

#include <algorithm>
#include <cmath>

namespace lensrt {

namespace cineon {
constexpr float kBlack = 95.0f, kWhite = 685.0f, kMaxCode = 1023.0f;
constexpr float kCodesPerDecade = 0.6f / 0.002f;
// Gain and offset that put linear 0 at the reference black.
inline float gain() {
  return 1.0f / (1.0f - std::pow(10.0f, (kBlack - kWhite) / kCodesPerDecade));
}
}  // namespace cineon

// Linear value -> code value in [0, 1023] (not rounded); negative values and
// NaN give the reference black, values beyond the film's range 1023.
inline float cineonEncode(float linear) {
  const float g = cineon::gain();
  const float v = std::isnan(linear) ? 0.0f : std::max(linear, 0.0f);
  const float code = cineon::kWhite + cineon::kCodesPerDecade * std::log10((v + g - 1.0f) / g);
  return std::clamp(code, 0.0f, cineon::kMaxCode);
}

// Code value in [0, 1023] -> linear, the inverse of cineonEncode.
inline float cineonDecode(float code) {
  const float g = cineon::gain();
  return std::pow(10.0f, (code - cineon::kWhite) / cineon::kCodesPerDecade) * g - (g - 1.0f);
}

}  // namespace lensrt
