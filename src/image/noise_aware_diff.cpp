#include "image/noise_aware_diff.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
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

namespace {

void checkInputs(const Image& a, const Image& b, const NoiseAwareOptions& o) {
  if (a.width != b.width || a.height != b.height || !hasVarianceChannels(a) || !hasVarianceChannels(b))
    throw std::invalid_argument("noiseAwareDiff: needs same-size images with R,G,B and variance.R/G/B");
  if (!(o.pixelFalseAlarmRate > 0 && o.pixelFalseAlarmRate < 1 && o.imageFalseAlarmRate > 0 &&
        o.imageFalseAlarmRate < 1))
    throw std::invalid_argument("noiseAwareDiff: false-alarm rates must be in (0,1)");
}

// One pixel's figures: for R,G,B the signed difference, the variance of
// the difference (with the floor) and |t|.
struct PixelTest {
  bool zeroVariance = true;        // variance.R/G/B zero in both images
  bool zeroVarianceFails = false;  // then: some |A-B| over the absolute threshold (or NaN)
  std::array<double, 3> difference{}, variance{}, mean{}, t{};
};

PixelTest testPixel(const Image& a, const Image& b, const std::array<int, 6>& ia,
                    const std::array<int, 6>& ib, int x, int y, const NoiseAwareOptions& o) {
  PixelTest p;
  for (int c = 0; c < 3; ++c)
    p.zeroVariance = p.zeroVariance && a.at(x, y, ia[3 + c]) == 0.0f && b.at(x, y, ib[3 + c]) == 0.0f;
  for (int c = 0; c < 3; ++c) {
    const double va = a.at(x, y, ia[c]), vb = b.at(x, y, ib[c]);
    const double diff = std::fabs(va - vb);
    p.difference[c] = va - vb;
    p.mean[c] = 0.5 * (std::fabs(va) + std::fabs(vb));
    if (p.zeroVariance) {
      p.zeroVarianceFails = p.zeroVarianceFails || !(diff <= o.absoluteThreshold);  // NaN fails
      continue;
    }
    const double floorSigma = o.relativeFloor * p.mean[c];
    p.variance[c] = std::max(0.0, double(a.at(x, y, ia[3 + c]))) +
                    std::max(0.0, double(b.at(x, y, ib[3 + c]))) + floorSigma * floorSigma;
    const double t = p.variance[c] > 0 ? diff / std::sqrt(p.variance[c]) : (diff > 0 ? kInf : 0.0);
    p.t[c] = std::isnan(t) ? kInf : t;
  }
  return p;
}

}  // namespace

NoiseAwareReport noiseAwareDiff(const Image& a, const Image& b, const NoiseAwareOptions& o) {
  checkInputs(a, b, o);
  const auto ia = colourAndVarianceChannels(a), ib = colourAndVarianceChannels(b);

  NoiseAwareReport r;
  // Adaptive renders say each pixel's samples in their spp channel: a pixel
  // is held to the t quantile of its own degrees of freedom.
  const int sppA = a.channelIndex("spp"), sppB = b.channelIndex("spp");
  const bool perPixel = sppA >= 0 || sppB >= 0;
  const auto pixelSamples = [&](int x, int y) {
    const int na = sppA >= 0 ? int(a.at(x, y, sppA)) : o.samplesA;
    const int nb = sppB >= 0 ? int(b.at(x, y, sppB)) : o.samplesB;
    return std::min(na, nb);
  };
  int minSamples = std::min(o.samplesA, o.samplesB);
  bool sameSamples = o.samplesA > 0 && o.samplesA == o.samplesB;
  if (perPixel) {
    minSamples = std::numeric_limits<int>::max();
    sameSamples = sppA >= 0 && sppB >= 0;
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        minSamples = std::min(minSamples, pixelSamples(x, y));
        sameSamples = sameSamples && a.at(x, y, sppA) == b.at(x, y, sppB);
      }
  }
  const auto dof = [](int samples) { return samples > 1 ? double(samples - 1) : 0.0; };
  r.degreesOfFreedom = dof(minSamples);  // the fewest: the gain test's shrink is then conservative
  const double channelAlpha = -std::expm1(std::log1p(-o.pixelFalseAlarmRate) / 3.0);  // Sidak
  r.criticalValue = twoSidedCriticalValue(channelAlpha, r.degreesOfFreedom);
  std::map<int, double> criticalBySamples;  // adaptive renders have a few dozen distinct counts
  const auto criticalAt = [&](int x, int y) {
    if (!perPixel) return r.criticalValue;
    const int n = pixelSamples(x, y);
    const auto it = criticalBySamples.find(n);
    if (it != criticalBySamples.end()) return it->second;
    return criticalBySamples[n] = twoSidedCriticalValue(channelAlpha, dof(n));
  };
  r.maxChannel = std::string(kColour[0]);  // not assign(const char*): GCC 12's false -Wrestrict (bug 105329)
  std::array<double, 3> fluxDifference{}, fluxVariance{}, fluxTotal{};
  // The gain test's sums: sum(m d / v) and sum(m^2 / v).
  std::array<double, 3> gainSum{}, gainNorm{};

  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      ++r.testedPixels;
      const PixelTest p = testPixel(a, b, ia, ib, x, y, o);
      if (p.zeroVariance) {
        ++r.zeroVariancePixels;
        r.zeroVarianceFailures += p.zeroVarianceFails;
        continue;
      }
      bool fails = false;
      const double critical = criticalAt(x, y);
      for (int c = 0; c < 3; ++c) {
        fluxDifference[c] += p.difference[c];
        fluxVariance[c] += p.variance[c];
        fluxTotal[c] += p.mean[c];
        if (p.variance[c] > 0) {
          gainSum[c] += p.mean[c] * p.difference[c] / p.variance[c];
          gainNorm[c] += p.mean[c] * p.mean[c] / p.variance[c];
        }
        if (p.t[c] > r.maxT) r.maxT = p.t[c], r.maxX = x, r.maxY = y, r.maxChannel = kColour[c];
        fails = fails || p.t[c] > critical;
      }
      r.statisticalFailures += fails;
    }
  r.failingPixels = r.zeroVarianceFailures + r.statisticalFailures;
  const long long statisticalPixels = r.testedPixels - r.zeroVariancePixels;
  // Half the image-level rate for the count test, a quarter each for the flux
  // and gain tests (a third of that per channel): Bonferroni keeps the total
  // at most beta.
  const double beta = o.imageFalseAlarmRate;
  r.expectedFailures = o.pixelFalseAlarmRate * double(statisticalPixels);
  r.allowedFailures = binomialCriticalCount(statisticalPixels, o.pixelFalseAlarmRate, beta / 2);
  const bool countPasses = r.failingPixels <= r.allowedFailures;

  r.fluxCriticalValue = twoSidedCriticalValue(beta / 12, 0.0);
  r.gainDecides = sameSamples;
  bool fluxPasses = true;
  for (int c = 0; c < 3; ++c) {
    const double sd = std::sqrt(fluxVariance[c]);
    r.fluxZ[c] = sd > 0 ? fluxDifference[c] / sd : 0.0;
    r.fluxRelativeDifference[c] = fluxTotal[c] > 0 ? fluxDifference[c] / fluxTotal[c] : 0.0;
    fluxPasses = fluxPasses && !(std::fabs(r.fluxZ[c]) > r.fluxCriticalValue);
    // The gain estimate g = sum(m d / v) / sum(m^2 / v) is the least-squares
    // fit of d = g m weighted by 1/v; its z is g / sd(g).
    // Weights from estimated variances (nu degrees of freedom) make the sum
    // vary more than its plug-in variance says, by about nu / (nu - 4), the
    // second moment of an inverse chi-square over its first: z is shrunk to
    // match (measured on normal samples at 16 spp: without it the rate of
    // false alarms doubles). Below 5 degrees of freedom that moment is
    // infinite, and the test is left out; with spp unknown z is taken as is.
    const double nu = r.degreesOfFreedom;
    const double shrink = nu == 0 ? 1.0 : nu > 4 ? std::sqrt((nu - 4) / nu) : 0.0;
    r.gainZ[c] = gainNorm[c] > 0 ? shrink * gainSum[c] / std::sqrt(gainNorm[c]) : 0.0;
    r.gainEstimate[c] = gainNorm[c] > 0 ? gainSum[c] / gainNorm[c] : 0.0;
    // Only renders of equal spp: Monte Carlo noise is skewed (rare bright
    // samples raise a pixel's mean and its variance together), and weights of
    // 1/v then favour the low side of the noisier image; with equal spp that
    // pull is the same on both sides and cancels (a 32- against a 128-spp
    // Cornell box scored z = -12.5).
    if (r.gainDecides) fluxPasses = fluxPasses && !(std::fabs(r.gainZ[c]) > r.fluxCriticalValue);
  }
  r.pass = countPasses && fluxPasses;
  return r;
}

std::vector<float> perPixelMaxT(const Image& a, const Image& b, const NoiseAwareOptions& o) {
  checkInputs(a, b, o);
  const auto ia = colourAndVarianceChannels(a), ib = colourAndVarianceChannels(b);
  std::vector<float> maxT(std::size_t(a.width) * a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const PixelTest p = testPixel(a, b, ia, ib, x, y, o);
      maxT[std::size_t(y) * a.width + x] = p.zeroVariance ? (p.zeroVarianceFails ? float(kInf) : 0.0f)
                                                          : float(std::max({p.t[0], p.t[1], p.t[2]}));
    }
  return maxT;
}

}  // namespace lensrt
