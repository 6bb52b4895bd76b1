// Noise-aware comparison of two Monte Carlo renders of (supposedly) the same
// scene, so that different seeds pass while real changes fail.
//
// Each image carries variance.R/G/B: the variance of each pixel's MEAN
// estimate (sample variance / spp). For channel c of a pixel
//     t = (a - b) / sqrt(var_a + var_b + (floor * (|a|+|b|)/2)^2)
// is, when both renders estimate the same value, close to Student's t with
// nu = min(spp_a, spp_b) - 1 degrees of freedom (a conservative Welch
// bound; normal when spp is unknown). The relative floor (default 0.2% of
// the value) keeps t finite where a low-spp render saw no variance by chance
// and absorbs float rounding; heavy-tailed MC noise (rare bright paths)
// makes small-spp variance estimates too low, which the t quantile and the
// floor temper but cannot remove: compare renders of at least ~16 spp.
//
// Three tests judge the image, the count test at half the stated
// image-level false-alarm rate beta and the flux and gain tests at a quarter
// each (Bonferroni), and it fails if any does:
//  - Count test, for local changes. A pixel fails when any of its R,G,B has
//    |t| > c, c set so a pixel of two equivalent renders fails with
//    probability alpha (the per-pixel false-alarm rate, split over the
//    channels by Sidak's rule, 1-(1-alpha)^(1/3) each: an upper bound on
//    the rate whatever the channels' correlation). Pixels whose variance is
//    zero in both images are instead held to the absolute threshold (a pixel
//    that saw no noise must match to rounding). With independent pixels the
//    count of failures is Binomial(N, alpha); the image fails when it
//    exceeds the k with P(X > k) <= beta/2.
//  - Flux test, for small global changes hidden in the noise (a 2% gain
//    moves each pixel by a fraction of a standard deviation, too little for
//    any one pixel to fail). Per channel, z = sum(A-B) / sqrt(sum(varA+varB))
//    is close to standard normal for unbiased renders (the central limit
//    theorem over pixels; valid for different spp too), tested two-sided at
//    beta/12 per channel.
//  - Gain test, for a change of exposure where a few noisy pixels (fireflies,
//    small bright lights) dominate the flux's variance. Per channel the
//    weighted least-squares gain g = sum(m d / v) / sum(m^2 / v) of the
//    differences d = A-B against the pixel means m = (|A|+|B|)/2, with v the
//    floored variance of d, has z = sum(m d / v) / sqrt(sum(m^2 / v)): the
//    matched filter of a gain, which weights each pixel by its signal to
//    noise. The weights are symmetric in A and B, so for equivalent renders
//    z is centred on 0 when both have the same spp (with different spp the
//    skew of Monte Carlo noise biases it, and the test only reports); it is
//    tested two-sided at beta/12 per channel (the golden suite measures the
//    false-alarm rate, tools/measure-false-alarms).
// An image with an "spp" channel (adaptive sampling: the samples each pixel
// took) has its own samples per pixel: the count test holds each pixel to
// the quantile for its own degrees of freedom, the gain test decides only
// when both images took the same samples in every pixel, and the degrees of
// freedom reported are the fewest.
// Both tests assume independent pixels (per-pixel sample streams, no
// filter splatting across pixels or denoising).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

struct NoiseAwareOptions {
  double pixelFalseAlarmRate = 1e-4;  // alpha
  double imageFalseAlarmRate = 1e-3;  // beta
  double relativeFloor = 2e-3;        // sigma floor as a fraction of the value
  double absoluteThreshold = 1e-6;    // for pixels with zero variance in both images
  int samplesA = 0, samplesB = 0;     // samples per pixel, 0 when unknown
};

struct NoiseAwareReport {
  double criticalValue = 0;     // c, the per-channel |t| threshold
  double degreesOfFreedom = 0;  // 0 means normal
  long long testedPixels = 0;   // all pixels
  long long zeroVariancePixels = 0;
  long long zeroVarianceFailures = 0;  // failing by the absolute threshold
  long long statisticalFailures = 0;   // failing by |t| > c
  long long failingPixels = 0;
  double expectedFailures = 0;                     // alpha * (pixels tested by t)
  long long allowedFailures = 0;                   // k, at beta/2
  std::array<double, 3> fluxZ{};                   // per R,G,B: sum(A-B) / sqrt(sum(varA+varB))
  std::array<double, 3> fluxRelativeDifference{};  // sum(A-B) / sum((|A|+|B|)/2)
  std::array<double, 3> gainZ{};                   // per R,G,B: the gain test's z
  std::array<double, 3> gainEstimate{};            // its weighted gain of A over B, minus 1
  bool gainDecides = false;                        // both spp known and equal: the gain test counts
  double fluxCriticalValue = 0;                    // |z| above this fails (flux and gain)
  double maxT = 0;                                 // largest |t| and where
  int maxX = 0, maxY = 0;
  std::string maxChannel;
  bool pass = true;
};

// True when the image has variance.R, variance.G and variance.B besides R,G,B.
bool hasVarianceChannels(const Image& image);

// Requires same-size images with R,G,B and variance.R/G/B (throws
// std::invalid_argument otherwise).
NoiseAwareReport noiseAwareDiff(const Image& a, const Image& b, const NoiseAwareOptions& options);

// Per-pixel largest |t| over R,G,B (row-major; +inf where a zero-variance
// pixel exceeds the absolute threshold, 0 where it does not): the input of
// a noise-aware heatmap. Same requirements as noiseAwareDiff.
std::vector<float> perPixelMaxT(const Image& a, const Image& b, const NoiseAwareOptions& options);

}  // namespace lensrt
