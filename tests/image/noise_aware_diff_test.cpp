#include "image/noise_aware_diff.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image_test_util.h"

namespace lensrt {
namespace {

using test::noisyRender;

constexpr int kSize = 96;
constexpr int kSpp = 64;
constexpr double kSampleNoise = 0.25;  // per-sample; the 64-sample mean has 3% noise

NoiseAwareOptions optionsFor(int spp) {
  NoiseAwareOptions o;
  o.samplesA = o.samplesB = spp;
  return o;
}

TEST(NoiseAwareDiff, DifferentSeedsPass) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const NoiseAwareReport r =
        noiseAwareDiff(noisyRender(kSize, kSize, 2 * seed, kSpp, kSampleNoise),
                       noisyRender(kSize, kSize, 2 * seed + 1, kSpp, kSampleNoise), optionsFor(kSpp));
    EXPECT_TRUE(r.pass) << "seed " << seed << ": " << r.failingPixels << " failing, " << r.allowedFailures
                        << " allowed; flux z " << r.fluxZ[0] << ", " << r.fluxZ[1] << ", " << r.fluxZ[2];
    EXPECT_EQ(r.degreesOfFreedom, kSpp - 1);
  }
}

TEST(NoiseAwareDiff, PixelFalseAlarmRateIsAsStated) {
  // At alpha = 1% the count of failing pixels of equivalent renders is
  // Binomial(9216, 0.01): mean 92, standard deviation 9.5.
  NoiseAwareOptions o = optionsFor(kSpp);
  o.pixelFalseAlarmRate = 0.01;
  long long total = 0;
  for (unsigned seed = 10; seed < 14; ++seed)
    total += noiseAwareDiff(noisyRender(kSize, kSize, 2 * seed, kSpp, kSampleNoise),
                            noisyRender(kSize, kSize, 2 * seed + 1, kSpp, kSampleNoise), o)
                 .failingPixels;
  const double expected = 4 * 0.01 * kSize * kSize, sd = std::sqrt(expected * 0.99);
  EXPECT_NEAR(double(total), expected, 4 * sd);
}

TEST(NoiseAwareDiff, TwoPercentGainFails) {
  const NoiseAwareReport r =
      noiseAwareDiff(noisyRender(kSize, kSize, 1, kSpp, kSampleNoise),
                     noisyRender(kSize, kSize, 2, kSpp, kSampleNoise, 1.02), optionsFor(kSpp));
  EXPECT_FALSE(r.pass);
  // The flux test sees it, with a relative flux difference of -2%.
  EXPECT_GT(std::fabs(r.fluxZ[1]), r.fluxCriticalValue);
  EXPECT_NEAR(r.fluxRelativeDifference[1], -0.02 / 1.01, 0.004);
}

// A few firefly pixels (bright, with a variance to match) dominate the flux's
// variance, so a 2% gain hides from the flux test; the gain test weights each
// pixel by its signal to noise and sees it.
TEST(NoiseAwareDiff, TheGainTestSeesAGainThatFirefliesHideFromTheFlux) {
  const auto withFireflies = [](Image image) {
    for (int k = 0; k < 20; ++k)
      for (int c = 0; c < 3; ++c) {
        const int x = (37 * k) % kSize, y = (53 * k + 11) % kSize;
        image.at(x, y, c) = 500.0f;
        image.at(x, y, 3 + c) = 4e4f;  // a standard deviation of 200
      }
    return image;
  };
  const Image reference = withFireflies(noisyRender(kSize, kSize, 3, kSpp, kSampleNoise));
  const NoiseAwareReport same = noiseAwareDiff(
      reference, withFireflies(noisyRender(kSize, kSize, 4, kSpp, kSampleNoise)), optionsFor(kSpp));
  EXPECT_TRUE(same.pass) << "gain z " << same.gainZ[1];
  Image gained = noisyRender(kSize, kSize, 4, kSpp, kSampleNoise, 1.02);
  gained = withFireflies(gained);
  const NoiseAwareReport r = noiseAwareDiff(reference, gained, optionsFor(kSpp));
  EXPECT_FALSE(r.pass);
  EXPECT_LT(std::fabs(r.fluxZ[1]), r.fluxCriticalValue) << "the flux test alone would see it";
  EXPECT_GT(std::fabs(r.gainZ[1]), r.fluxCriticalValue);
  EXPECT_NEAR(r.gainEstimate[1], -0.02, 0.004);  // sum(m d / v) / sum(m^2 / v): A over B, minus 1
}

// The gain test's z is close to standard normal for equivalent renders, also
// at 16 samples a pixel (variance estimates with 15 degrees of freedom): at
// an image alpha of 0.24 each channel is tested at 0.02, so about 6% of 300
// pairs fail it (18, standard deviation 4.1).
TEST(NoiseAwareDiff, TheGainTestsFalseAlarmRateIsAsStated) {
  NoiseAwareOptions o = optionsFor(16);
  o.imageFalseAlarmRate = 0.24;
  o.pixelFalseAlarmRate = 1e-9;  // the count test out of the way
  int gainFailures = 0;
  for (unsigned seed = 100; seed < 400; ++seed) {
    const NoiseAwareReport r = noiseAwareDiff(noisyRender(48, 48, 2 * seed, 16, kSampleNoise),
                                              noisyRender(48, 48, 2 * seed + 1, 16, kSampleNoise), o);
    gainFailures += std::fabs(r.gainZ[0]) > r.fluxCriticalValue ||
                    std::fabs(r.gainZ[1]) > r.fluxCriticalValue ||
                    std::fabs(r.gainZ[2]) > r.fluxCriticalValue;
  }
  EXPECT_NEAR(gainFailures, 18, 4 * 4.1) << "false alarms of the gain test in 300 pairs";
}

// With different or unknown spp the gain test reports but does not decide.
TEST(NoiseAwareDiff, TheGainTestDecidesOnlyForEqualSpp) {
  const Image a = noisyRender(kSize, kSize, 5, kSpp, kSampleNoise);
  const Image b = noisyRender(kSize, kSize, 6, kSpp, kSampleNoise, 1.02);
  NoiseAwareOptions o = optionsFor(kSpp);
  const NoiseAwareReport equal = noiseAwareDiff(a, b, o);
  EXPECT_TRUE(equal.gainDecides);
  EXPECT_GT(std::fabs(equal.gainZ[1]), equal.fluxCriticalValue);
  o.samplesB = 2 * kSpp;
  const NoiseAwareReport differ = noiseAwareDiff(a, b, o);
  EXPECT_FALSE(differ.gainDecides);
  EXPECT_GT(std::fabs(differ.gainZ[1]), differ.fluxCriticalValue);  // still reported
  o.samplesA = o.samplesB = 0;
  EXPECT_FALSE(noiseAwareDiff(a, b, o).gainDecides);
}

// Adaptive renders: an "spp" channel gives each pixel its own degrees of
// freedom. A pixel 10 standard errors off fails at 64 samples (critical |t|
// about 4.6) and passes at 3 (over 100 with 2 degrees of freedom).
Image withSppChannel(const Image& image, float spp) {
  Image out(image.width, image.height, image.channels);
  out.channels.push_back("spp");
  out.pixels.clear();
  for (std::size_t i = 0; i < image.pixels.size(); i += image.channelCount()) {
    out.pixels.insert(out.pixels.end(), image.pixels.begin() + std::ptrdiff_t(i),
                      image.pixels.begin() + std::ptrdiff_t(i + image.channelCount()));
    out.pixels.push_back(spp);
  }
  return out;
}

TEST(NoiseAwareDiff, AnSppChannelGivesEachPixelItsOwnDegreesOfFreedom) {
  const Image a = noisyRender(16, 16, 7, kSpp, kSampleNoise);
  Image b = a;
  const int r = b.channelIndex("R"), v = b.channelIndex("variance.R");
  b.at(3, 4, r) += 10.0f * std::sqrt(2.0f * a.at(3, 4, v));
  Image sparse = withSppChannel(a, 64.0f), sparseB = withSppChannel(b, 64.0f);
  EXPECT_EQ(noiseAwareDiff(sparse, sparseB, {}).statisticalFailures, 1);
  sparse.at(3, 4, sparse.channelIndex("spp")) = 3.0f;  // fewest samples of the two images count
  const NoiseAwareReport few = noiseAwareDiff(sparse, sparseB, {});
  EXPECT_EQ(few.statisticalFailures, 0);
  EXPECT_EQ(few.degreesOfFreedom, 2.0);  // the fewest anywhere
  EXPECT_FALSE(few.gainDecides);         // the images' samples differ in a pixel
  EXPECT_TRUE(noiseAwareDiff(withSppChannel(a, 64.0f), sparseB, {}).gainDecides);
  // Without the channel and with spp unknown, the normal quantile fails it.
  EXPECT_EQ(noiseAwareDiff(a, b, {}).statisticalFailures, 1);
}

TEST(NoiseAwareDiff, OnePixelShiftFails) {
  const NoiseAwareReport r =
      noiseAwareDiff(noisyRender(kSize, kSize, 1, kSpp, kSampleNoise),
                     noisyRender(kSize, kSize, 2, kSpp, kSampleNoise, 1.0, 1), optionsFor(kSpp));
  EXPECT_FALSE(r.pass);
  // The check edges (one column in four) fail pixel by pixel.
  EXPECT_GT(r.failingPixels, kSize * kSize / 8);
}

TEST(NoiseAwareDiff, ZeroVariancePixelsUseTheAbsoluteThreshold) {
  Image a = noisyRender(8, 8, 1, kSpp, kSampleNoise);
  for (int c = 3; c < 6; ++c) a.at(2, 2, c) = 0.0f;
  Image b = a;
  NoiseAwareOptions o = optionsFor(kSpp);
  o.absoluteThreshold = 1e-3;
  b.at(2, 2, 0) += 5e-4f;
  NoiseAwareReport r = noiseAwareDiff(a, b, o);
  EXPECT_EQ(r.zeroVariancePixels, 1);
  EXPECT_EQ(r.zeroVarianceFailures, 0);
  b.at(2, 2, 0) += 1e-3f;
  r = noiseAwareDiff(a, b, o);
  EXPECT_EQ(r.zeroVarianceFailures, 1);
}

TEST(NoiseAwareDiff, TStatisticByHand) {
  Image a = test::constantImage(2, 1, {"R", "G", "B", "variance.R", "variance.G", "variance.B"}, 0.01f);
  Image b = a;
  a.at(0, 0, 0) = 1.0f, b.at(0, 0, 0) = 1.3f;  // t = 0.3 / sqrt(0.01 + 0.01)
  b.at(1, 0, 4) = 0.03f;                       // same values, more variance: t = 0
  NoiseAwareOptions o;
  o.relativeFloor = 0;
  const std::vector<float> t = perPixelMaxT(a, b, o);
  EXPECT_NEAR(t[0], (1.3f - 1.0f) / std::sqrt(0.02), 1e-5);
  EXPECT_EQ(t[1], 0.0f);
  // With the floor, sigma^2 gains (floor * (|a|+|b|)/2)^2.
  o.relativeFloor = 0.1;
  EXPECT_NEAR(perPixelMaxT(a, b, o)[0], 0.3 / std::sqrt(0.02 + 0.115 * 0.115), 1e-5);
  const NoiseAwareReport r = noiseAwareDiff(a, b, o);
  EXPECT_NEAR(r.maxT, 0.3 / std::sqrt(0.02 + 0.115 * 0.115), 1e-5);
  EXPECT_EQ(r.maxX, 0);
  EXPECT_EQ(r.maxChannel, "R");
}

TEST(NoiseAwareDiff, RequiresVarianceChannels) {
  const Image plain = test::constantImage(4, 4, {"R", "G", "B"}, 0.5f);
  EXPECT_FALSE(hasVarianceChannels(plain));
  EXPECT_TRUE(hasVarianceChannels(noisyRender(4, 4, 1, 4, 0.1)));
  EXPECT_THROW(noiseAwareDiff(plain, plain, {}), std::invalid_argument);
}

}  // namespace
}  // namespace lensrt
