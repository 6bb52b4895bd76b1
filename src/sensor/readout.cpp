#include "sensor/readout.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  double normal() {
    // Box-Muller, one of the pair.
    const double r = std::sqrt(-2.0 * std::log(open()));
    return r * std::cos(2.0 * 3.14159265358979323846 * uniform());
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

// Purposes: each draws from its own stream.
constexpr std::uint64_t kShot = 0x73686f74, kDark = 0x6461726b, kRead = 0x72656164, kPrnu = 0x70726e75,
                        kDsnu = 0x64736e75;

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
  PixelStream shot(seed, x, y, channel, kShot), dark(seed, x, y, channel, kDark),
      read(seed, x, y, channel, kRead);
  // The fixed patterns belong to the sensor, not to the render.
  PixelStream prnu(p.fixedPatternSeed, x, y, channel, kPrnu), dsnu(p.fixedPatternSeed, x, y, channel, kDsnu);
  const double photo = shot.poisson(signal);
  const double darkMean = meanDark * std::max(0.0, 1.0 + p.dsnuPercent / 100.0 * dsnu.normal());
  const double thermal = dark.poisson(darkMean);
  const double gain = std::max(0.0, 1.0 + p.prnuPercent / 100.0 * prnu.normal());
  const double noise = p.readNoiseE * read.normal();
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
  for (int y = 0; y < image.height; ++y)
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
  image = std::move(out);
}

}  // namespace lensrt
