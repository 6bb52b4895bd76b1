// Noise-aware comparison of two Monte Carlo renders of (supposedly) the same scene,
// so that different seeds pass while real changes fail: per-pixel Student t scores
// from the variance channels, judged by a count test, a flux test and a gain test
// (Bonferroni over the image's false-alarm rate). The statistics and their
// assumptions: docs/design/noise-aware-diff.md.
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
