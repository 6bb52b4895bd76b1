// Numeric comparison of two images, with the thresholds and verdicts of
// OpenImageIO's idiff so its users know what to expect:
//  - a channel value fails when |a-b| > fail AND |a-b| / ((|a|+|b|)/2) >
//    failRelative (likewise for warnings); a pixel fails when any channel does;
//  - the verdict is Fail when more than failPercent % of the pixels fail or
//    the largest error exceeds hardFail, else Warn by the same rules with the
//    warning thresholds, else Pass.
// NaN against a number counts as an infinite error; equal NaNs or equal
// infinities count as no error, so an image always equals itself.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

struct DiffThresholds {
  double fail = 1e-6;
  double failRelative = 0.0;
  double failPercent = 0.0;
  double hardFail = std::numeric_limits<double>::infinity();
  double warn = 1e-6;
  double warnRelative = 0.0;
  double warnPercent = 0.0;
  double hardWarn = std::numeric_limits<double>::infinity();
  // Mean relative error divides by max((|a|+|b|)/2, relativeFloor), so black
  // pixels do not divide by zero.
  double relativeFloor = 0.01;
};

enum class DiffVerdict { Pass = 0, Warn = 1, Fail = 2 };
const char* verdictName(DiffVerdict verdict);

struct DiffStats {
  std::string channel;  // "all" for the figures over every channel
  double maxError = 0;  // largest |a-b|, and where (first such pixel)
  int maxX = 0, maxY = 0;
  std::string maxChannel;
  double meanError = 0;          // mean |a-b|
  double rmse = 0;               // sqrt(mean (a-b)^2)
  double psnr = 0;               // 10 log10(1 / mse), peak 1.0 as in idiff; +inf when equal
  double meanRelativeError = 0;  // mean |a-b| / max((|a|+|b|)/2, floor)
  long long failCount = 0;       // pixels (or, per channel, values) over the fail thresholds
  long long warnCount = 0;
  double failPercent = 0;  // of the pixel count
  double warnPercent = 0;
};

struct DiffReport {
  int width = 0, height = 0;
  std::vector<DiffStats> channels;  // in the first image's channel order
  DiffStats overall;                // counts are of pixels with any channel over
  DiffVerdict verdict = DiffVerdict::Pass;
};

// Why two images cannot be compared (different size or channel names), or
// nothing when they can. Channels are matched by name, not position.
std::optional<std::string> incomparableReason(const Image& a, const Image& b);

// Requires comparable images (see incomparableReason); throws
// std::invalid_argument otherwise.
DiffReport diffImages(const Image& a, const Image& b, const DiffThresholds& thresholds);

// Per-pixel largest |a-b| over the channels (NaN mismatches as +inf),
// row-major: the input of an error heatmap.
std::vector<float> perPixelMaxError(const Image& a, const Image& b);

// Channel k of `a` is channel result[k] of `b` (requires comparable images).
std::vector<int> matchChannels(const Image& a, const Image& b);

}  // namespace lensrt
