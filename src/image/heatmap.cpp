#include "image/heatmap.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "image/text.h"

namespace lensrt {
namespace {

namespace OIIO = OIIO_NAMESPACE;

constexpr Rgb kBackground{0.02f, 0.02f, 0.02f};
constexpr Rgb kNonFinite{1.0f, 0.0f, 1.0f};

// Viridis through OpenImageIO, whose maps are in linear values already.
std::vector<float> viridis(std::vector<float> normalised, int width, int height) {
  // Wraps the vector's memory: the ImageBuf does not outlive this call.
  OIIO::ImageBuf src(OIIO::ImageSpec(width, height, 1, OIIO::TypeDesc::FLOAT), normalised.data());
  const OIIO::ImageBuf mapped = OIIO::ImageBufAlgo::color_map(src, 0, "viridis");
  if (mapped.has_error()) throw std::runtime_error("heatmap: " + mapped.geterror());
  std::vector<float> rgb(std::size_t(width) * height * 3);
  mapped.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  return rgb;
}

void fill(Image& image, int x0, int y0, int x1, int y1, const Rgb& colour) {
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = colour[c];
}

}  // namespace

std::string formatScaleLabel(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

double heatmapScale(const std::vector<float>& error, const HeatmapOptions& options) {
  if (options.scaleMax > 0) return options.scaleMax;
  double largest = 0;
  for (const float e : error)
    if (std::isfinite(e)) largest = std::max(largest, double(e));
  return largest > 0 ? largest : 1.0;  // all equal: any scale shows uniform zero
}

Image makeHeatmap(const std::vector<float>& error, int width, int height, const HeatmapOptions& options) {
  if (width <= 0 || height <= 0 || error.size() != std::size_t(width) * height)
    throw std::invalid_argument("makeHeatmap: error buffer does not match the size");
  const double scale = heatmapScale(error, options);

  std::vector<float> normalised(error.size());
  for (std::size_t i = 0; i < error.size(); ++i)
    normalised[i] = std::isfinite(error[i]) ? float(std::clamp(error[i] / scale, 0.0, 1.0)) : 0.0f;
  const std::vector<float> map = viridis(normalised, width, height);

  const TextStyle style{12, {0.9f, 0.9f, 0.9f}};
  const std::string labels[3] = {formatScaleLabel(scale), formatScaleLabel(scale / 2), "0"};
  int labelWidth = 0;
  for (const auto& l : labels) labelWidth = std::max(labelWidth, textWidth(l, style));
  const int margin = 8, barWidth = 16;
  const int panelWidth =
      margin + std::max(barWidth + 6 + labelWidth, textWidth(options.title, style)) + margin;
  const int titleHeight = options.title.empty() ? 0 : style.size + 6;
  const int canvasHeight = std::max(height, 96 + titleHeight);

  Image out(width + panelWidth, canvasHeight, {"R", "G", "B"});
  fill(out, 0, 0, out.width, out.height, kBackground);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = std::isfinite(error[i]) ? map[i * 3 + c] : kNonFinite[c];
    }

  // The bar runs from the top label's centre (max) down to the bottom one (0).
  if (!options.title.empty()) drawText(out, width + margin, margin / 2, options.title, style);
  const int barTop = titleHeight + margin + style.size / 2,
            barBottom = canvasHeight - margin - style.size / 2;
  const int barX = width + margin;
  const int barRows = std::max(1, barBottom - barTop);
  std::vector<float> ramp(barRows);
  for (int r = 0; r < barRows; ++r) ramp[r] = 1.0f - float(r) / float(std::max(1, barRows - 1));
  const std::vector<float> rampColours = viridis(ramp, 1, barRows);
  for (int r = 0; r < barRows; ++r)
    fill(out, barX, barTop + r, barX + barWidth, barTop + r + 1,
         {rampColours[r * 3], rampColours[r * 3 + 1], rampColours[r * 3 + 2]});
  const int labelX = barX + barWidth + 6;
  const int labelY[3] = {barTop, (barTop + barBottom) / 2, barBottom};
  for (int i = 0; i < 3; ++i) drawText(out, labelX, labelY[i] - style.size / 2, labels[i], style);
  return out;
}

}  // namespace lensrt
