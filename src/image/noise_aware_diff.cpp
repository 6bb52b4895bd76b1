#include "image/noise_aware_diff.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "image/statistics.h"

namespace lensrt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::array<const char*, 3> kColour{"R", "G", "B"};
constexpr std::array<const char*, 3> kVariance{"variance.R", "variance.G", "variance.B"};

std::array<int, 6> colourAndVarianceChannels(const Image& image) {
  std::array<int, 6> index{};
  for (int c = 0; c < 3; ++c) {
    index[c] = image.channelIndex(kColour[c]);
    index[3 + c] = image.channelIndex(kVariance[c]);
  }
  return index;
}

}  // namespace

bool hasVarianceChannels(const Image& image) {
  const auto index = colourAndVarianceChannels(image);
  return std::all_of(index.begin(), index.end(), [](int i) { return i >= 0; });
}

NoiseAwareReport noiseAwareDiff(const Image& a, const Image& b, const NoiseAwareOptions& o) {
  if (a.width != b.width || a.height != b.height || !hasVarianceChannels(a) || !hasVarianceChannels(b))
    throw std::invalid_argument("noiseAwareDiff: needs same-size images with R,G,B and variance.R/G/B");
  if (!(o.pixelFalseAlarmRate > 0 && o.pixelFalseAlarmRate < 1 && o.imageFalseAlarmRate > 0 &&
        o.imageFalseAlarmRate < 1))
    throw std::invalid_argument("noiseAwareDiff: false-alarm rates must be in (0,1)");
  const auto ia = colourAndVarianceChannels(a), ib = colourAndVarianceChannels(b);

  NoiseAwareReport r;
  const int minSamples = std::min(o.samplesA, o.samplesB);
  r.degreesOfFreedom = minSamples > 1 ? double(minSamples - 1) : 0.0;
  const double channelAlpha = -std::expm1(std::log1p(-o.pixelFalseAlarmRate) / 3.0);  // Sidak
  r.criticalValue = twoSidedCriticalValue(channelAlpha, r.degreesOfFreedom);
  r.maxChannel = kColour[0];
  std::array<double, 3> fluxDifference{}, fluxVariance{}, fluxTotal{};

  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      ++r.testedPixels;
      bool zeroVariance = true;
      for (int c = 0; c < 3; ++c)
        zeroVariance = zeroVariance && a.at(x, y, ia[3 + c]) == 0.0f && b.at(x, y, ib[3 + c]) == 0.0f;
      bool fails = false;
      for (int c = 0; c < 3; ++c) {
        const double va = a.at(x, y, ia[c]), vb = b.at(x, y, ib[c]);
        const double diff = std::fabs(va - vb);
        if (zeroVariance) {
          fails = fails || !(diff <= o.absoluteThreshold);  // NaN fails
          continue;
        }
        const double mean = 0.5 * (std::fabs(va) + std::fabs(vb));
        const double floorSigma = o.relativeFloor * mean;
        const double variance = std::max(0.0, double(a.at(x, y, ia[3 + c]))) +
                                std::max(0.0, double(b.at(x, y, ib[3 + c]))) + floorSigma * floorSigma;
        fluxDifference[c] += va - vb;
        fluxVariance[c] += variance;
        fluxTotal[c] += mean;
        const double t = variance > 0 ? diff / std::sqrt(variance) : (diff > 0 ? kInf : 0.0);
        const double tOrInf = std::isnan(t) ? kInf : t;
        if (tOrInf > r.maxT) r.maxT = tOrInf, r.maxX = x, r.maxY = y, r.maxChannel = kColour[c];
        fails = fails || tOrInf > r.criticalValue;
      }
      if (zeroVariance) {
        ++r.zeroVariancePixels;
        r.zeroVarianceFailures += fails;
      } else {
        r.statisticalFailures += fails;
      }
    }
  r.failingPixels = r.zeroVarianceFailures + r.statisticalFailures;
  const long long statisticalPixels = r.testedPixels - r.zeroVariancePixels;
  // Half the image-level rate for the count test, half for the flux tests
  // (a third of that per channel): Bonferroni keeps the total at most beta.
  const double beta = o.imageFalseAlarmRate;
  r.expectedFailures = o.pixelFalseAlarmRate * double(statisticalPixels);
  r.allowedFailures = binomialCriticalCount(statisticalPixels, o.pixelFalseAlarmRate, beta / 2);
  const bool countPasses = r.failingPixels <= r.allowedFailures;

  r.fluxCriticalValue = twoSidedCriticalValue(beta / 6, 0.0);
  bool fluxPasses = true;
  for (int c = 0; c < 3; ++c) {
    const double sd = std::sqrt(fluxVariance[c]);
    r.fluxZ[c] = sd > 0 ? fluxDifference[c] / sd : 0.0;
    r.fluxRelativeDifference[c] = fluxTotal[c] > 0 ? fluxDifference[c] / fluxTotal[c] : 0.0;
    fluxPasses = fluxPasses && !(std::fabs(r.fluxZ[c]) > r.fluxCriticalValue);
  }
  r.pass = countPasses && fluxPasses;
  return r;
}

}  // namespace lensrt
