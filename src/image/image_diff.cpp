#include "image/image_diff.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace lensrt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// |a-b|, with equal values (infinities included) and NaN pairs as 0 and a
// NaN against anything else as +inf, so NaNs can never hide.
double valueError(float a, float b) {
  if (a == b || (std::isnan(a) && std::isnan(b))) return 0.0;
  const double d = std::fabs(double(a) - double(b));
  return std::isnan(d) ? kInf : d;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

// Running sums for one set of values; turned into DiffStats at the end.
struct Accumulator {
  double maxError = -1;
  int maxX = 0, maxY = 0, maxChannel = 0;
  double sumError = 0, sumSquared = 0, sumRelative = 0;
  long long count = 0, failCount = 0, warnCount = 0;

  void add(double d, double relative, int x, int y, int c) {
    if (d > maxError) maxError = d, maxX = x, maxY = y, maxChannel = c;
    sumError += d;
    sumSquared += d * d;
    sumRelative += relative;
    ++count;
  }

  DiffStats stats(std::string name, const std::vector<std::string>& channelNames,
                  long long pixelCount) const {
    DiffStats s;
    s.channel = std::move(name);
    s.maxError = std::max(maxError, 0.0);
    s.maxX = maxX, s.maxY = maxY;
    s.maxChannel = channelNames.empty() ? "" : channelNames[maxChannel];
    const double n = double(std::max<long long>(count, 1));
    s.meanError = sumError / n;
    const double mse = sumSquared / n;
    s.rmse = std::sqrt(mse);
    s.psnr = mse > 0 ? 10.0 * std::log10(1.0 / mse) : kInf;
    s.meanRelativeError = sumRelative / n;
    s.failCount = failCount;
    s.warnCount = warnCount;
    s.failPercent = pixelCount ? 100.0 * double(failCount) / double(pixelCount) : 0.0;
    s.warnPercent = pixelCount ? 100.0 * double(warnCount) / double(pixelCount) : 0.0;
    return s;
  }
};

}  // namespace

const char* verdictName(DiffVerdict verdict) {
  switch (verdict) {
    case DiffVerdict::Pass:
      return "PASS";
    case DiffVerdict::Warn:
      return "WARNING";
    case DiffVerdict::Fail:
      return "FAILURE";
  }
  return "?";
}

std::optional<std::string> incomparableReason(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    return "sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " versus " +
           std::to_string(b.width) + "x" + std::to_string(b.height);
  const std::set<std::string> setA(a.channels.begin(), a.channels.end());
  const std::set<std::string> setB(b.channels.begin(), b.channels.end());
  if (setA != setB || setA.size() != a.channels.size() || setB.size() != b.channels.size())
    return "channels differ: " + joinNames(a.channels) + " versus " + joinNames(b.channels);
  return std::nullopt;
}

std::vector<int> matchChannels(const Image& a, const Image& b) {
  if (incomparableReason(a, b)) throw std::invalid_argument("diffImages: images are not comparable");
  std::vector<int> map;
  for (const auto& name : a.channels) map.push_back(b.channelIndex(name));
  return map;
}

DiffReport diffImages(const Image& a, const Image& b, const DiffThresholds& t) {
  const std::vector<int> bChannel = matchChannels(a, b);
  const int nc = int(a.channelCount());
  const long long pixelCount = (long long)a.width * a.height;
  std::vector<Accumulator> perChannel(nc);
  Accumulator all;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      bool pixelFails = false, pixelWarns = false;
      for (int c = 0; c < nc; ++c) {
        const float va = a.at(x, y, c), vb = b.at(x, y, bChannel[c]);
        const double d = valueError(va, vb);
        const double mean = 0.5 * (std::fabs(double(va)) + std::fabs(double(vb)));
        // d is finite exactly when both values are, and then so is mean.
        const double relative = std::isinf(d) ? kInf : d / std::max(mean, t.relativeFloor);
        // The idiff rule: over both the absolute and the relative threshold.
        const bool fails = d > t.fail && d > t.failRelative * mean;
        const bool warns = d > t.warn && d > t.warnRelative * mean;
        perChannel[c].add(d, relative, x, y, c);
        perChannel[c].failCount += fails;
        perChannel[c].warnCount += warns;
        all.add(d, relative, x, y, c);
        pixelFails |= fails;
        pixelWarns |= warns;
      }
      all.failCount += pixelFails;
      all.warnCount += pixelWarns;
    }

  DiffReport report;
  report.width = a.width;
  report.height = a.height;
  for (int c = 0; c < nc; ++c)
    report.channels.push_back(perChannel[c].stats(a.channels[c], a.channels, pixelCount));
  report.overall = all.stats("all", a.channels, pixelCount);
  const auto& o = report.overall;
  const double pixels = double(pixelCount);
  if (double(o.failCount) > t.failPercent / 100.0 * pixels || o.maxError > t.hardFail)
    report.verdict = DiffVerdict::Fail;
  else if (double(o.warnCount) > t.warnPercent / 100.0 * pixels || o.maxError > t.hardWarn)
    report.verdict = DiffVerdict::Warn;
  return report;
}

std::vector<float> perPixelMaxError(const Image& a, const Image& b) {
  const std::vector<int> bChannel = matchChannels(a, b);
  std::vector<float> error(std::size_t(a.width) * a.height, 0.0f);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double m = 0;
      for (int c = 0; c < int(a.channelCount()); ++c)
        m = std::max(m, valueError(a.at(x, y, c), b.at(x, y, bChannel[c])));
      error[std::size_t(y) * a.width + x] = float(m);
    }
  return error;
}

}  // namespace lensrt
