#include "sensor/readout.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace lensrt {
namespace {

std::uint64_t splitMix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A stream of uniform numbers for one pixel, channel and purpose.
class PixelStream {
 public:
  PixelStream(std::uint64_t seed, int x, int y, int channel, std::uint64_t purpose)
      : state_(splitMix(splitMix(splitMix(seed ^ purpose) ^ std::uint64_t(std::uint32_t(x))) ^
                        (std::uint64_t(std::uint32_t(y)) << 8 | std::uint64_t(channel)))) {}

  // In [0, 1), 53 bits.
  double uniform() { return double(splitMix(state_++) >> 11) * 0x1.0p-53; }
  // In (0, 1): safe for logarithms.
  double open() { return (double(splitMix(state_++) >> 11) + 0.5) * 0x1.0p-53; }
  double normal() { return normalPair().first; }
  // Marsaglia's polar method: two independent normals from one logarithm
  // and no sines (a point of the unit disc, 1.27 tries on average).
  std::pair<double, double> normalPair() {
    for (;;) {
      const double u = 2.0 * uniform() - 1.0, v = 2.0 * uniform() - 1.0, s = u * u + v * v;
      if (s > 0.0 && s < 1.0) {
        const double f = std::sqrt(-2.0 * std::log(s) / s);
        return {u * f, v * f};
      }
    }
  }
  // Poisson by multiplication for small means, PTRS (Hoermann 1993) above 10.
  double poisson(double mean) {
    if (!(mean > 0.0)) return 0.0;
    if (mean < 10.0) {
      const double limit = std::exp(-mean);
      double product = uniform(), k = 0.0;
      while (product > limit) {
        product *= uniform();
        k += 1.0;
      }
      return k;
    }
    const double slam = std::sqrt(mean), loglam = std::log(mean);
    const double b = 0.931 + 2.53 * slam, a = -0.059 + 0.02483 * b;
    const double invAlpha = 1.1239 + 1.1328 / (b - 3.4), vr = 0.9277 - 3.6224 / (b - 2.0);
    for (;;) {
      const double u = uniform() - 0.5, v = open(), us = 0.5 - std::abs(u);
      const double k = std::floor((2.0 * a / us + b) * u + mean + 0.43);
      if (us >= 0.07 && v <= vr) return k;
      if (k < 0.0 || (us < 0.013 && v > us)) continue;
      if (std::log(v) + std::log(invAlpha) - std::log(a / (us * us) + b) <=
          -mean + k * loglam - std::lgamma(k + 1.0))
        return k;
    }
  }

 private:
  std::uint64_t state_;
};

// The two streams of a pixel: temporal noise (the render's seed) and fixed patterns (the sensor's).
constexpr std::uint64_t kTemporal = 0x74656d70, kFixed = 0x66697864;

}  // namespace

SensorExposure physicalSensorExposure(const SensorParams& p, double iso, double shutterSeconds,
                                      double pixelAreaM2) {
  if (!(iso > 0.0) || !(pixelAreaM2 > 0.0))
    throw std::invalid_argument("ISO and pixel area must be positive");
  SensorExposure e;
  e.electronsPerValue = 78.0 / iso * kPhotonsPerLuxSecondM2 * pixelAreaM2 * p.quantumEfficiency;
  e.exposureSeconds = shutterSeconds;
  e.analogGain = iso / p.baseIso;
  return e;
}

SensorExposure normalizedSensorExposure(const SensorParams& p, double shutterSeconds) {
  SensorExposure e;
  e.electronsPerValue = p.fullWellE;
  e.exposureSeconds = shutterSeconds;
  e.analogGain = 1.0;
  return e;
}

double readoutDn(const SensorParams& p, const SensorExposure& e, double value, int x, int y, int channel,
                 std::uint64_t seed) {
  // Far above full well the reading is clipped anyway; the cap keeps the
  // Poisson draw finite for any value.
  constexpr double kMaxElectrons = 1e15;
  const double signal = std::min(std::max(0.0, value) * e.electronsPerValue, kMaxElectrons);
  const double meanDark = std::min(p.darkCurrentEPerS * e.exposureSeconds, kMaxElectrons);
  // The fixed patterns belong to the sensor, not to the render: one pair of
  // normals from the sensor's seed gives the pixel's PRNU gain and DSNU.
  // Draws whose parameter is 0 are skipped (they would change nothing).
  std::pair<double, double> fixed{0.0, 0.0};
  if (p.prnuPercent > 0 || (p.dsnuPercent > 0 && meanDark > 0))
    fixed = PixelStream(p.fixedPatternSeed, x, y, channel, kFixed).normalPair();
  // The temporal noise, in order from one stream of the render's seed.
  PixelStream temporal(seed, x, y, channel, kTemporal);
  const double photo = signal > 0 ? temporal.poisson(signal) : 0.0;
  const double darkMean = meanDark * std::max(0.0, 1.0 + p.dsnuPercent / 100.0 * fixed.second);
  const double thermal = darkMean > 0 ? temporal.poisson(darkMean) : 0.0;
  const double gain = std::max(0.0, 1.0 + p.prnuPercent / 100.0 * fixed.first);
  const double noise = p.readNoiseE > 0 ? p.readNoiseE * temporal.normal() : 0.0;
  const double electrons = std::min(photo * gain + thermal + noise, p.fullWellE);
  const double dn = std::round(p.blackLevelDn + electrons * p.gainDnPerE * e.analogGain);
  return std::clamp(dn, 0.0, p.maxDn());
}

double dnToValue(const SensorParams& p, const SensorExposure& e, double dn) {
  return (dn - p.blackLevelDn) / (p.gainDnPerE * e.analogGain) / e.electronsPerValue;
}

void applySensorReadout(Image& image, const SensorParams& p, const SensorExposure& e, std::uint64_t seed) {
  const int first = image.channelIndex("R");
  if (first < 0 || image.channelIndex("G") != first + 1 || image.channelIndex("B") != first + 2)
    throw std::invalid_argument("the sensor reads R, G, B channels side by side");
  const std::size_t oldCount = image.channelCount();
  Image out(image.width, image.height, image.channels);
  out.originX = image.originX, out.originY = image.originY;
  out.frameWidth = image.frameWidth, out.frameHeight = image.frameHeight;
  for (const char* name : {"noiseless.R", "noiseless.G", "noiseless.B"}) out.channels.push_back(name);
  const std::size_t count = out.channelCount();
  out.pixels.assign(std::size_t(image.width) * image.height * count, 0.0f);
  // Rows in parallel: every number is keyed by its pixel, so the order of
  // the work changes nothing.
  tbb::parallel_for(0, image.height, [&](int y) {
    for (int x = 0; x < image.width; ++x) {
      const float* in = &image.pixels[(std::size_t(y) * image.width + x) * oldCount];
      float* o = &out.pixels[(std::size_t(y) * image.width + x) * count];
      std::copy(in, in + oldCount, o);
      for (int c = 0; c < 3; ++c) {
        const double value = in[first + c];
        o[oldCount + c] = float(value);
        const double dn = readoutDn(p, e, value, image.originX + x, image.originY + y, c, seed);
        o[first + c] = float(dnToValue(p, e, dn));
      }
    }
  });
  image = std::move(out);
}

}  // namespace lensrt
