// False-colour maps of per-pixel error with a labelled colour bar.
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

struct HeatmapOptions {
  double scaleMax = 0;          // error shown at the top of the bar; 0: the largest finite error
  std::string title = "|A-B|";  // what the values are, printed above the bar
};

// `error` holds width*height non-negative values, row-major. The result is
// a linear RGB image (write it as .png for the intended sRGB colours): the
// map in viridis (0 dark blue, scaleMax and above yellow; infinite or NaN
// errors magenta), then to its right the title and a colour bar labelled
// 0, half and max.
Image makeHeatmap(const std::vector<float>& error, int width, int height, const HeatmapOptions& options = {});

// The scale makeHeatmap uses for these errors and options.
double heatmapScale(const std::vector<float>& error, const HeatmapOptions& options);

// Short label for a scale value, e.g. "0.25", "1.5e-05".
std::string formatScaleLabel(double value);

}  // namespace lensrt
