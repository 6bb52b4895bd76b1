// The film's spectral response for dispersion: each channel's response
// integrates to 1 and the sampled weights average to 1, so a grey scene
// keeps its value whatever the wavelengths.
#include "render/spectral_response.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace lensrt {
namespace {

TEST(SpectralResponse, EachChannelIntegratesToOne) {
  double r = 0, g = 0, b = 0;
  const int n = 40000;
  const double step = (kWavelengthMaxNm - kWavelengthMinNm) / n;
  for (int i = 0; i < n; ++i) {
    const Rgb v = spectralResponse(kWavelengthMinNm + (i + 0.5) * step);
    r += v.x * step, g += v.y * step, b += v.z * step;
  }
  EXPECT_NEAR(r, 1.0, 1e-4);
  EXPECT_NEAR(g, 1.0, 1e-4);
  EXPECT_NEAR(b, 1.0, 1e-4);
  // Red peaks in the red, blue in the blue.
  EXPECT_GT(spectralResponse(620).x, spectralResponse(620).z);
  EXPECT_GT(spectralResponse(450).z, spectralResponse(450).x);
  EXPECT_EQ(spectralResponse(300).y, 0.0f);
}

TEST(SpectralResponse, SampledWeightsAverageToOneAndStayBounded) {
  const int n = 100000;
  double r = 0, g = 0, b = 0, lo = 1e9, hi = -1e9;
  for (int i = 0; i < n; ++i) {
    const WavelengthSample s = sampleWavelength(float((i + 0.5) / n));
    EXPECT_GE(s.wavelengthNm, kWavelengthMinNm);
    EXPECT_LT(s.wavelengthNm, kWavelengthMaxNm);
    r += s.weight.x / n, g += s.weight.y / n, b += s.weight.z / n;
    for (const float w : {s.weight.x, s.weight.y, s.weight.z})
      lo = std::min(lo, double(w)), hi = std::max(hi, double(w));
  }
  EXPECT_NEAR(r, 1.0, 1e-3);
  EXPECT_NEAR(g, 1.0, 1e-3);
  EXPECT_NEAR(b, 1.0, 1e-3);
  // Drawn from the channels' mean: r_c / pdf = 3 r_c / (r_R + r_G + r_B) <= 3,
  // a little more where the 1 nm table's steps lag the steep tails.
  EXPECT_GE(lo, 0.0);
  EXPECT_LE(hi, 3.2);
  // Monotonic in u (inverse CDF): stratified u gives stratified wavelengths.
  EXPECT_LT(sampleWavelength(0.25f).wavelengthNm, sampleWavelength(0.75f).wavelengthNm);
}

}  // namespace
}  // namespace lensrt
