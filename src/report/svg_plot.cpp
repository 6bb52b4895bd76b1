#include "report/svg_plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace lensrt {

namespace {
double niceStep(double lo, double hi, int count) {
  const double span = std::max(hi - lo, 1e-12);
  const double raw = span / std::max(count, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) return m * mag;
  return 10.0 * mag;
}

std::string tickLabel(double v, double step) {
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  if (std::abs(v) < step * 1e-6) v = 0.0;
  return fmt::format("{:.{}f}", v, decimals);
}
}  // namespace

std::vector<double> niceTicks(double lo, double hi, int count) {
  const double step = niceStep(lo, hi, count);
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) ticks.push_back(t);
  return ticks;
}

void widenToTicks(double& lo, double& hi, int count) {
  const double step = niceStep(lo, hi, count);
  lo = std::floor(lo / step + 1e-9) * step;
  hi = std::ceil(hi / step - 1e-9) * step;
  if (hi <= lo) hi = lo + step;
}

PlotFrame::PlotFrame(Vec2d corner, double w, double h, PlotAxis x, PlotAxis y)
    : corner_(corner), w_(w), h_(h), x_(std::move(x)), y_(std::move(y)) {}

Vec2d PlotFrame::map(Vec2d d) const {
  return {corner_.x + (d.x - x_.lo) / (x_.hi - x_.lo) * w_,
          corner_.y + h_ - (d.y - y_.lo) / (y_.hi - y_.lo) * h_};
}

void PlotFrame::drawAxes(Svg& svg) const {
  const double xStep = niceStep(x_.lo, x_.hi, x_.ticks), yStep = niceStep(y_.lo, y_.hi, y_.ticks);
  svg.beginGroup("class=\"axes\"");
  for (const double t : niceTicks(x_.lo, x_.hi, x_.ticks)) {
    const Vec2d p = map({t, y_.lo});
    svg.line({p.x, corner_.y}, {p.x, corner_.y + h_}, "class=\"grid\"");
    svg.line(p, {p.x, p.y + 5}, "class=\"tick\"");
    svg.text({p.x, p.y + 19}, tickLabel(t, xStep), "class=\"ticklabel\" text-anchor=\"middle\"");
  }
  for (const double t : niceTicks(y_.lo, y_.hi, y_.ticks)) {
    const Vec2d p = map({x_.lo, t});
    svg.line({corner_.x, p.y}, {corner_.x + w_, p.y}, "class=\"grid\"");
    svg.line({p.x - 5, p.y}, p, "class=\"tick\"");
    svg.text({p.x - 8, p.y + 4}, tickLabel(t, yStep), "class=\"ticklabel\" text-anchor=\"end\"");
  }
  svg.rect(corner_, w_, h_, "class=\"frame\"");
  svg.text({corner_.x + w_ / 2, corner_.y + h_ + 42}, x_.title, "class=\"axistitle\" text-anchor=\"middle\"");
  const Vec2d yt{corner_.x - 52, corner_.y + h_ / 2};
  svg.text(yt, y_.title,
           fmt::format("class=\"axistitle\" text-anchor=\"middle\" transform=\"rotate(-90 {} {})\"",
                       Svg::num(yt.x), Svg::num(yt.y)));
  svg.endGroup();
}

void PlotFrame::series(Svg& svg, const std::vector<Vec2d>& data, const std::string& attributes) const {
  std::vector<Vec2d> page;
  for (const Vec2d& d : data) {
    // Clamp into the frame: curves never spill over labels.
    const Vec2d p = map(d);
    page.push_back({std::clamp(p.x, corner_.x, corner_.x + w_), std::clamp(p.y, corner_.y, corner_.y + h_)});
  }
  svg.polyline(page, attributes);
}

std::string plotCss() {
  return R"(text { fill: #222; }
.title { font-size: 20px; font-weight: bold; }
.subtitle { font-size: 13px; fill: #444; }
.note { font-size: 12px; fill: #555; }
.ticklabel { font-size: 12px; fill: #333; }
.axistitle { font-size: 14px; }
.grid { stroke: #e3e3e3; stroke-width: 1; }
.tick { stroke: #333; stroke-width: 1; }
.frame { fill: none; stroke: #333; stroke-width: 1.2; }
.legend { font-size: 13px; paint-order: stroke; stroke: white; stroke-width: 3px; stroke-linejoin: round; }
)";
}

}  // namespace lensrt
