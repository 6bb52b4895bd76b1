// The film's spectral response, for cameras that trace each sample at its own
// wavelength (dispersion). The renderer carries RGB radiance (a scene's colour
// is not upsampled to a spectrum), so a sample at wavelength l adds its path's
// RGB radiance times w_c(l) = r_c(l) / pdf(l) to channel c, where each
// response r_c integrates to 1 over 380-780 nm: the expected pixel value is the
// RGB one (a grey scene stays grey), only the image geometry depends on l.
//
// The responses are smooth sensor-like curves, not the CIE functions (whose
// sRGB transform has negative lobes, i.e. negative weights and more noise):
// truncated Gaussians, blue 455 nm / sigma 28 nm, green 535 / 32, red 605 / 32.
// Wavelengths are drawn from their mean (so every weight is between 0 and 3),
// from a 1 nm piecewise-constant table.
#pragma once

#include "core/vec.h"

namespace lensrt {

// Wavelengths handed to the camera lie in this range (nm).
inline constexpr float kWavelengthMinNm = 380.0f;
inline constexpr float kWavelengthMaxNm = 780.0f;

// r_R, r_G, r_B at a wavelength, per nm (0 outside the range).
Rgb spectralResponse(double wavelengthNm);

struct WavelengthSample {
  float wavelengthNm = 550.0f;
  Rgb weight{1, 1, 1};  // r_c / pdf
};
// u uniform in [0, 1) -> a wavelength and its channel weights.
WavelengthSample sampleWavelength(float u);

}  // namespace lensrt
