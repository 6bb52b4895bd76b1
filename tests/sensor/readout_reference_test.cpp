// The readout gives the bits of its definition: a reference written the
// straightforward way (one value at a time, each stream drawn from its
// pixel's three hashes, std::round, the DN's value computed per value) and
// the library's staged, batched readout agree bit for bit over every
// preset, both exposure modes, the paths that skip draws, Poisson means on
// both sides of 10, negative and huge values, and images large enough for
// the DN table and too small for it. Renders, tiles and resumes are compared
// bit for bit, so a faster readout must not change a single one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>

#include "sensor/readout.h"
#include "sensor/sensor_params.h"

namespace lensrt {
namespace {

namespace reference {

std::uint64_t splitMix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

class PixelStream {
 public:
  PixelStream(std::uint64_t seed, int x, int y, int channel, std::uint64_t purpose)
      : state_(splitMix(splitMix(splitMix(seed ^ purpose) ^ std::uint64_t(std::uint32_t(x))) ^
                        (std::uint64_t(std::uint32_t(y)) << 8 | std::uint64_t(channel)))) {}
  double uniform() { return double(splitMix(state_++) >> 11) * 0x1.0p-53; }
  double open() { return (double(splitMix(state_++) >> 11) + 0.5) * 0x1.0p-53; }
  double normal() { return normalPair().first; }
  std::pair<double, double> normalPair() {
    for (;;) {
      const double u = 2.0 * uniform() - 1.0, v = 2.0 * uniform() - 1.0, s = u * u + v * v;
      if (s > 0.0 && s < 1.0) {
        const double f = std::sqrt(-2.0 * std::log(s) / s);
        return {u * f, v * f};
      }
    }
  }
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

constexpr std::uint64_t kTemporal = 0x74656d70, kFixed = 0x66697864;

double readoutDn(const SensorParams& p, const SensorExposure& e, double value, int x, int y, int channel,
                 std::uint64_t seed) {
  constexpr double kMaxElectrons = 1e15;
  const double signal = std::min(std::max(0.0, value) * e.electronsPerValue, kMaxElectrons);
  const double meanDark = std::min(p.darkCurrentEPerS * e.exposureSeconds, kMaxElectrons);
  std::pair<double, double> fixed{0.0, 0.0};
  if (p.prnuPercent > 0 || (p.dsnuPercent > 0 && meanDark > 0))
    fixed = PixelStream(p.fixedPatternSeed, x, y, channel, kFixed).normalPair();
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

}  // namespace reference

std::uint64_t bits(double v) {
  std::uint64_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
std::uint32_t bits(float v) {
  std::uint32_t b = 0;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::vector<SensorParams> sensors() {
  std::vector<SensorParams> all = sensorPresets();
  SensorParams quiet;  // no fixed patterns, no dark current, no read noise: the draws skipped
  quiet.name = "quiet";
  quiet.prnuPercent = quiet.dsnuPercent = quiet.darkCurrentEPerS = quiet.readNoiseE = 0.0;
  all.push_back(quiet);
  SensorParams hot = quiet;  // dark current alone, with means above 10 (PTRS)
  hot.name = "hot";
  hot.darkCurrentEPerS = 5000.0;
  hot.dsnuPercent = 30.0;
  all.push_back(hot);
  return all;
}

std::vector<SensorExposure> exposures(const SensorParams& p) {
  return {normalizedSensorExposure(p, 0.01), physicalSensorExposure(p, 100.0, 0.01, 16e-12),
          physicalSensorExposure(p, 3200.0, 0.5, 4e-12)};
}

TEST(ReadoutReference, ReadoutDnHasTheBitsOfItsDefinition) {
  int compared = 0;
  for (const SensorParams& p : sensors())
    for (const SensorExposure& e : exposures(p))
      for (const double value : {-1.0, -0.0, 0.0, 1e-5, 3e-4, 0.002, 0.02, 0.3, 0.9, 1.0, 2.5, 1e6, 1e300})
        for (int y = -1; y < 3; ++y)
          for (int x = 0; x < 9; ++x)
            for (int c = 0; c < 3; ++c) {
              const double expected = reference::readoutDn(p, e, value, x * 97 - 5, y * 1001, c, 42);
              const double got = readoutDn(p, e, value, x * 97 - 5, y * 1001, c, 42);
              ASSERT_EQ(bits(got), bits(expected)) << p.name << " value " << value << " at " << x << "," << y;
              ++compared;
            }
  EXPECT_EQ(compared, 6 * 3 * 13 * 4 * 9 * 3);
}

// Whole images: R, G, B read out, noiseless.R/G/B added, other channels kept,
// placed by their origin in the frame.
TEST(ReadoutReference, ApplySensorReadoutHasTheBitsOfItsDefinition) {
  for (const SensorParams& p : sensors())
    for (const SensorExposure& e : exposures(p))
      for (const auto& [w, h] : {std::pair{131, 9}, std::pair{3, 2}}) {  // with and without the DN table
        SCOPED_TRACE(p.name + " " + std::to_string(w));
        Image image(w, h, {"A", "R", "G", "B", "Z"});
        image.originX = 100, image.originY = 7;
        image.frameWidth = 400, image.frameHeight = 300;
        for (std::size_t i = 0; i < image.pixels.size(); ++i)
          image.pixels[i] = float((i * 2654435761u) % 1000) / 700.0f - 0.1f;
        image.pixels[1] = 0.0f;  // exactly black
        const Image before = image;
        applySensorReadout(image, p, e, 9);
        ASSERT_EQ(image.channelCount(), 8u);
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x) {
            EXPECT_EQ(bits(image.at(x, y, 0)), bits(before.at(x, y, 0)));
            EXPECT_EQ(bits(image.at(x, y, 4)), bits(before.at(x, y, 4)));
            for (int c = 0; c < 3; ++c) {
              const double value = before.at(x, y, 1 + c);
              const double dn = reference::readoutDn(p, e, value, 100 + x, 7 + y, c, 9);
              ASSERT_EQ(bits(image.at(x, y, 1 + c)), bits(float(dnToValue(p, e, dn))))
                  << x << "," << y << "," << c;
              ASSERT_EQ(bits(image.at(x, y, 5 + c)), bits(float(value)));
            }
          }
      }
}

// A reading of -0.0 (a black level of 0 and a negative noise rounding to
// zero) keeps its sign through the DN table: machine-vision reads dark
// pixels both sides of zero.
TEST(ReadoutReference, NegativeZeroReadingsKeepTheirSign) {
  const SensorParams p = sensorParams("machine-vision");
  const SensorExposure e = normalizedSensorExposure(p, 0.01);
  Image image(128, 64, {"R", "G", "B"});
  applySensorReadout(image, p, e, 3);
  int negativeZeros = 0;
  for (int i = 0; i < 128 * 64 * 3; ++i)
    if (image.pixels[std::size_t(i / 3) * 6 + std::size_t(i % 3)] == 0.0f &&
        std::signbit(image.pixels[std::size_t(i / 3) * 6 + std::size_t(i % 3)]))
      ++negativeZeros;
  EXPECT_GT(negativeZeros, 0);
}

}  // namespace
}  // namespace lensrt
