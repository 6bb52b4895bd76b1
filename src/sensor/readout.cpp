#include "sensor/readout.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace lensrt {
namespace {

std::uint64_t splitMix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The stream of one pixel, channel and purpose starts at
// splitMix(splitMix(splitMix(seed ^ purpose) ^ x) ^ (y << 8 | channel)): the
// first hash is the purpose's and the second its column's, shared by the
// values that differ only in the later parts.
std::uint64_t purposeKey(std::uint64_t seed, std::uint64_t purpose) {
  return splitMix(seed ^ purpose);
}
std::uint64_t columnKey(std::uint64_t purposeKey, int x) {
  return splitMix(purposeKey ^ std::uint64_t(std::uint32_t(x)));
}
std::uint64_t streamStart(std::uint64_t columnKey, int y, int channel) {
  return splitMix(columnKey ^ (std::uint64_t(std::uint32_t(y)) << 8 | std::uint64_t(channel)));
}

// Poisson draws of means from 10 by PTRS (Hoermann 1993): the constants of a
// mean, the two draws of a trial, and the trial, which gives k or -1 to
// draw again.
struct Ptrs {
  double mean, b, a, vr;
  explicit Ptrs(double m)
      : mean(m), b(0.931 + 2.53 * std::sqrt(m)), a(-0.059 + 0.02483 * b), vr(0.9277 - 3.6224 / (b - 2.0)) {}
};
struct PtrsTry {
  double u, v;
};
// The exact test, where the squeeze failed (about one trial in seven): out
// of line, so that the trial's common path stays short.
[[gnu::noinline]] bool ptrsExact(const Ptrs& c, double v, double us, double k) {
  const double invAlpha = 1.1239 + 1.1328 / (c.b - 3.4), loglam = std::log(c.mean);
  return std::log(v) + std::log(invAlpha) - std::log(c.a / (us * us) + c.b) <=
         -c.mean + k * loglam - std::lgamma(k + 1.0);
}
double ptrsTrial(const Ptrs& c, PtrsTry t) {
  const double us = 0.5 - std::abs(t.u);
  const double k = std::floor((2.0 * c.a / us + c.b) * t.u + c.mean + 0.43);
  if (us >= 0.07 && t.v <= c.vr) return k;
  if (k < 0.0 || (us < 0.013 && t.v > us)) return -1.0;
  return ptrsExact(c, t.v, us, k) ? k : -1.0;
}

// A stream of uniform numbers for one pixel, channel and purpose.
class PixelStream {
 public:
  explicit PixelStream(std::uint64_t start = 0) : state_(start) {}

  // In [0, 1), 53 bits.
  double uniform() { return double(splitMix(state_++) >> 11) * 0x1.0p-53; }
  // In (0, 1): safe for logarithms.
  double open() { return (double(splitMix(state_++) >> 11) + 0.5) * 0x1.0p-53; }
  double normal() { return normalPair().first; }

  // Marsaglia's polar method: two independent normals from one logarithm
  // and no sines (a point of the unit disc, 1.27 tries on average).
  struct PolarTry {
    double u, v, s;
    bool inDisc() const { return s > 0.0 && s < 1.0; }
    std::pair<double, double> normals() const {
      const double f = std::sqrt(-2.0 * std::log(s) / s);
      return {u * f, v * f};
    }
  };
  PolarTry polarTry() {
    const double u = 2.0 * uniform() - 1.0, v = 2.0 * uniform() - 1.0;
    return {u, v, u * u + v * v};
  }
  std::pair<double, double> normalPair() {
    for (;;)
      if (const PolarTry t = polarTry(); t.inDisc()) return t.normals();
  }

  // Poisson by multiplication for small means, PTRS from kPtrsMean.
  static constexpr double kPtrsMean = 10.0;
  double poisson(double mean) {
    if (!(mean > 0.0)) return 0.0;
    if (mean < kPtrsMean) {
      double product = uniform(), k = 0.0;
      // exp(-mean) > 1 - mean, and the library's exp is within an ulp: a
      // first draw below 1 - mean - 2^-50 ends the loop whatever exp(-mean)
      // rounds to, so exp is needed only for the draws above (small means,
      // as dark current's, mostly draw 0).
      if (product <= 1.0 - mean - 0x1p-50) return 0.0;
      const double limit = std::exp(-mean);
      while (product > limit) {
        product *= uniform();
        k += 1.0;
      }
      return k;
    }
    return ptrs(Ptrs(mean));
  }

  PtrsTry ptrsTry() {
    const double u = uniform() - 0.5, v = open();
    return {u, v};
  }
  double ptrs(const Ptrs& c) {
    for (;;)
      if (const double k = ptrsTrial(c, ptrsTry()); k >= 0.0) return k;
  }

 private:
  std::uint64_t state_;
};

// The two streams of a pixel: temporal noise (the render's seed) and fixed patterns (the sensor's).
constexpr std::uint64_t kTemporal = 0x74656d70, kFixed = 0x66697864;

// Far above full well the reading is clipped anyway; the cap keeps the
// Poisson draw finite for any value.
constexpr double kMaxElectrons = 1e15;

// std::round's result (half away from zero, the sign kept, -0.3 -> -0.0)
// without its library call, which x86-64's baseline cannot inline.
double roundHalfAway(double x) {
  if (!(std::abs(x) < 0x1p52)) return std::round(x);  // already an integer, or not finite
  const double whole = double(std::int64_t(x));       // toward zero, exact below 2^52
  const double rest = x - whole;                      // exact
  // Without branches (readings fall on either side at random); the sums are exact.
  return std::copysign(whole + double(rest >= 0.5) - double(rest <= -0.5), x);
}

// One readout's constants and its two purposes' keys: readoutDn makes one
// per value, applySensorReadout one per image.
class Reader {
 public:
  Reader(const SensorParams& p, const SensorExposure& e, std::uint64_t seed)
      : p_(p),
        e_(e),
        fixedKey_(purposeKey(p.fixedPatternSeed, kFixed)),
        temporalKey_(purposeKey(seed, kTemporal)),
        meanDark_(std::min(p.darkCurrentEPerS * e.exposureSeconds, kMaxElectrons)),
        // Draws whose parameter is 0 are skipped (they would change nothing).
        drawFixed_(p.prnuPercent > 0 || (p.dsnuPercent > 0 && meanDark_ > 0)) {}

  std::uint64_t fixedColumn(int x) const { return columnKey(fixedKey_, x); }
  std::uint64_t temporalColumn(int x) const { return columnKey(temporalKey_, x); }

  // A value to read out, with the starts of its two streams.
  struct Site {
    double value;
    std::uint64_t fixedStart, temporalStart;
  };
  static constexpr int kMaxSites = 96;
  Site site(double value, std::uint64_t fixedColumn, std::uint64_t temporalColumn, int y, int channel) const {
    return {value, streamStart(fixedColumn, y, channel), streamStart(temporalColumn, y, channel)};
  }

  // The DN of up to kMaxSites values. Each value's numbers are its own, drawn
  // in the same order as one at a time; the values go through each stage
  // side by side, in short loops whose iterations are independent, so that
  // the CPU overlaps their chains of long operations (logarithms, divisions,
  // square roots).
  void dn(const Site* sites, int n, double* dn) const {
    // The fixed patterns belong to the sensor, not to the render: one pair of
    // normals from the sensor's seed gives the pixel's PRNU gain and DSNU.
    // Each stage draws every value's first try, then finishes the values
    // whose try succeeded and goes on drawing for the others.
    std::pair<double, double> fixed[kMaxSites];
    PixelStream fixedStream[kMaxSites], temporal[kMaxSites];
    PixelStream::PolarTry polar[kMaxSites];
    if (drawFixed_) {
      for (int i = 0; i < n; ++i) {
        fixedStream[i] = PixelStream(sites[i].fixedStart);
        polar[i] = fixedStream[i].polarTry();
      }
      for (int i = 0; i < n; ++i)
        fixed[i] = polar[i].inDisc() ? polar[i].normals() : fixedStream[i].normalPair();
    } else {
      std::fill(fixed, fixed + n, std::pair<double, double>{0.0, 0.0});
    }
    // The temporal noise, in order from one stream of the render's seed.
    double photo[kMaxSites], thermal[kMaxSites], noise[kMaxSites], signal[kMaxSites];
    PtrsTry ptrsTry[kMaxSites] = {};
    for (int i = 0; i < n; ++i) {
      temporal[i] = PixelStream(sites[i].temporalStart);
      signal[i] = std::min(std::max(0.0, sites[i].value) * e_.electronsPerValue, kMaxElectrons);
      if (signal[i] >= PixelStream::kPtrsMean) ptrsTry[i] = temporal[i].ptrsTry();
    }
    for (int i = 0; i < n; ++i) {
      if (!(signal[i] >= PixelStream::kPtrsMean)) {
        photo[i] = signal[i] > 0 ? temporal[i].poisson(signal[i]) : 0.0;
        continue;
      }
      const Ptrs c(signal[i]);
      const double k = ptrsTrial(c, ptrsTry[i]);
      photo[i] = k >= 0.0 ? k : temporal[i].ptrs(c);
    }
    for (int i = 0; i < n; ++i) {
      const double darkMean = meanDark_ * std::max(0.0, 1.0 + p_.dsnuPercent / 100.0 * fixed[i].second);
      thermal[i] = darkMean > 0 ? temporal[i].poisson(darkMean) : 0.0;
    }
    if (p_.readNoiseE > 0) {
      for (int i = 0; i < n; ++i) polar[i] = temporal[i].polarTry();
      for (int i = 0; i < n; ++i)
        noise[i] = p_.readNoiseE * (polar[i].inDisc() ? polar[i].normals() : temporal[i].normalPair()).first;
    } else {
      std::fill(noise, noise + n, 0.0);
    }
    for (int i = 0; i < n; ++i) {
      const double gain = std::max(0.0, 1.0 + p_.prnuPercent / 100.0 * fixed[i].first);
      const double electrons = std::min(photo[i] * gain + thermal[i] + noise[i], p_.fullWellE);
      dn[i] = std::clamp(roundHalfAway(p_.blackLevelDn + electrons * p_.gainDnPerE * e_.analogGain), 0.0,
                         p_.maxDn());
    }
  }

 private:
  const SensorParams& p_;
  const SensorExposure& e_;
  std::uint64_t fixedKey_, temporalKey_;
  double meanDark_;
  bool drawFixed_;
};

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
  const Reader reader(p, e, seed);
  const Reader::Site site = reader.site(value, reader.fixedColumn(x), reader.temporalColumn(x), y, channel);
  double dn = 0.0;
  reader.dn(&site, 1, &dn);
  return dn;
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
  const Reader reader(p, e, seed);
  // A DN is an integer from 0 to the ADC's maximum: its value in image units
  // comes from a table when the image has more values than the table (-0.0,
  // whose value may be -0.0, excepted).
  std::vector<float> valueOfDn;
  if (std::size_t(image.width) * std::size_t(image.height) * 3 > std::size_t(p.maxDn()) + 1)
    for (double dn = 0.0; dn <= p.maxDn(); dn += 1.0) valueOfDn.push_back(float(dnToValue(p, e, dn)));
  // The keys of the frame's columns this image holds.
  std::vector<std::uint64_t> fixedColumns, temporalColumns;
  for (int x = 0; x < image.width; ++x) {
    fixedColumns.push_back(reader.fixedColumn(image.originX + x));
    temporalColumns.push_back(reader.temporalColumn(image.originX + x));
  }
  // Rows in parallel: every number is keyed by its pixel, so the order of
  // the work changes nothing.
  tbb::parallel_for(0, image.height, [&](int y) {
    constexpr int kPixels = Reader::kMaxSites / 3;
    for (int x0 = 0; x0 < image.width; x0 += kPixels) {
      const int n = std::min(kPixels, image.width - x0);
      Reader::Site sites[Reader::kMaxSites];
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
          sites[3 * i + c] = reader.site(image.at(x0 + i, y, first + c), fixedColumns[std::size_t(x0 + i)],
                                         temporalColumns[std::size_t(x0 + i)], image.originY + y, c);
      double dn[Reader::kMaxSites];
      reader.dn(sites, 3 * n, dn);
      for (int i = 0; i < n; ++i) {
        const float* in = &image.pixels[(std::size_t(y) * image.width + std::size_t(x0 + i)) * oldCount];
        float* o = &out.pixels[(std::size_t(y) * image.width + std::size_t(x0 + i)) * count];
        std::copy(in, in + oldCount, o);
        for (int c = 0; c < 3; ++c) {
          const double v = dn[3 * i + c];
          o[oldCount + c] = float(double(in[first + c]));  // as the value read out
          o[first + c] =
              !valueOfDn.empty() && !std::signbit(v) ? valueOfDn[std::size_t(v)] : float(dnToValue(p, e, v));
        }
      }
    }
  });
  image = std::move(out);
}

double clippedShare(const Image& image, const SensorParams& p, const SensorExposure& e) {
  const int first = image.channelIndex("R");
  if (first < 0 || image.channelIndex("G") != first + 1 || image.channelIndex("B") != first + 2)
    throw std::invalid_argument("the sensor reads R, G, B channels side by side");
  if (image.width <= 0 || image.height <= 0) return 0.0;
  // As Reader::dn clips: the full well's DN, or the ADC's top.
  const double saturationDn =
      std::min(p.maxDn(), roundHalfAway(p.blackLevelDn + p.fullWellE * p.gainDnPerE * e.analogGain));
  const float saturation = float(dnToValue(p, e, saturationDn));
  std::size_t clipped = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      clipped += image.at(x, y, first) >= saturation || image.at(x, y, first + 1) >= saturation ||
                 image.at(x, y, first + 2) >= saturation;
  return double(clipped) / (double(image.width) * double(image.height));
}

}  // namespace lensrt
