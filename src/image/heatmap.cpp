#include "image/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "image/text.h"

namespace lensrt {
namespace {

constexpr Rgb kBackground{0.02f, 0.02f, 0.02f};
constexpr Rgb kNonFinite{1.0f, 0.0f, 1.0f};

// Viridis (matplotlib's, by Smith and van der Walt, public domain CC0) as 17
// evenly spaced knots in linear values: the table OpenImageIO's color_map
// interpolated before, so heatmaps look as they did.
constexpr std::array<Rgb, 17> kViridis{{
    {0.057951f, 0.000377f, 0.088657f},
    {0.064791f, 0.009258f, 0.145340f},
    {0.063189f, 0.025975f, 0.198994f},
    {0.054539f, 0.051494f, 0.237655f},
    {0.043139f, 0.084803f, 0.258811f},
    {0.032927f, 0.124348f, 0.268148f},
    {0.025232f, 0.169666f, 0.271584f},
    {0.019387f, 0.221569f, 0.270909f},
    {0.014846f, 0.281323f, 0.263855f},
    {0.013529f, 0.349530f, 0.246357f},
    {0.021457f, 0.425216f, 0.215605f},
    {0.049317f, 0.505412f, 0.172291f},
    {0.112305f, 0.585164f, 0.121207f},
    {0.229143f, 0.657992f, 0.070438f},
    {0.417964f, 0.717561f, 0.029928f},
    {0.683952f, 0.762557f, 0.009977f},
    {0.984709f, 0.799651f, 0.018243f},
}};

// Piecewise linear between the knots; `t` is clamped to [0, 1].
Rgb viridis(float t) {
  const float x = std::clamp(t, 0.0f, 1.0f) * float(kViridis.size() - 1);
  const int i = std::min(int(x), int(kViridis.size()) - 2);
  const float f = x - float(i);
  Rgb rgb;
  for (int c = 0; c < 3; ++c) rgb[c] = kViridis[i][c] + f * (kViridis[i + 1][c] - kViridis[i][c]);
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
      const Rgb colour = std::isfinite(error[i]) ? viridis(normalised[i]) : kNonFinite;
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = colour[c];
    }

  // The bar runs from the top label's centre (max) down to the bottom one (0).
  if (!options.title.empty()) drawText(out, width + margin, margin / 2, options.title, style);
  const int barTop = titleHeight + margin + style.size / 2,
            barBottom = canvasHeight - margin - style.size / 2;
  const int barX = width + margin;
  const int barRows = std::max(1, barBottom - barTop);
  for (int r = 0; r < barRows; ++r)
    fill(out, barX, barTop + r, barX + barWidth, barTop + r + 1,
         viridis(1.0f - float(r) / float(std::max(1, barRows - 1))));
  const int labelX = barX + barWidth + 6;
  const int labelY[3] = {barTop, (barTop + barBottom) / 2, barBottom};
  for (int i = 0; i < 3; ++i) drawText(out, labelX, labelY[i] - style.size / 2, labels[i], style);
  return out;
}

}  // namespace lensrt
