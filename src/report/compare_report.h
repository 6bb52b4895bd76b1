// The figures and pages of `lensrt compare`: per-model statistics of the
// four renders, report.json and a static report.html that shows them.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

inline constexpr int kVignettingBins = 10;

// Mean luminance (Rec. 709 of R,G,B) in kVignettingBins rings of equal radius
// step from the image centre to a corner, each divided by the centre bin's
// (so bin 0 is 1). A bin without pixels or a black centre gives NaN.
std::vector<double> vignettingProfile(const Image& image);

// Mean of a channel over the image; NaN when the channel is absent.
double channelMean(const Image& image, const std::string& channel);
// Mean Rec. 709 luminance of R,G,B.
double meanLuminance(const Image& image);

// report.html from report.json's document (see compare_command.cpp for its
// keys): the contact sheet, the heat maps, a table and the vignetting chart.
std::string compareReportHtml(const nlohmann::json& report);

// An inline SVG line chart of the vignetting profiles, one line per model.
std::string vignettingChartSvg(const std::vector<std::string>& models,
                               const std::vector<std::vector<double>>& profiles);

}  // namespace lensrt
