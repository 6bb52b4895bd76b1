#include "render/adaptive_sampling.h"

#include <algorithm>

namespace lensrt {

double relativeStandardError(const PixelAccumulator& pixel) {
  const PixelAccumulator::MeanAndError m = pixel.meanAndError();
  double error = 0, mean = 0;
  for (int k = 0; k < 3; ++k) {
    error += m.standardError[k];
    mean += std::max(m.mean[k], 0.0);
  }
  return error / std::max(mean, 3 * kAdaptiveDarkFloor);
}

namespace {
int stepAfter(int samples) {
  return std::max(1, samples / 8);
}
}  // namespace

bool isDecisionPoint(const AdaptiveSampling& adaptive, int samples) {
  int d = std::max(1, adaptive.minSamples);
  if (samples < d) return false;
  while (d < samples) d += stepAfter(d);
  return d == samples;
}

int nextDecisionPoint(const AdaptiveSampling& adaptive, int samples) {
  int d = std::max(1, adaptive.minSamples);
  while (d <= samples) d += stepAfter(d);
  return d;
}

bool keepsSampling(const AdaptiveSampling& adaptive, const PixelAccumulator& pixel, int samplesDone) {
  if (pixel.samplesTaken() != std::uint64_t(samplesDone)) return false;  // stopped at an earlier point
  if (!isDecisionPoint(adaptive, samplesDone)) return true;
  return !(relativeStandardError(pixel) < adaptive.noiseThreshold);
}

}  // namespace lensrt
