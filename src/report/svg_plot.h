// Plot frames for SVG charts: a data rectangle mapped to a page rectangle,
// with a box, grid, "nice" ticks (1, 2, 5 x 10^k), tick labels and axis titles.
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"
#include "report/svg_writer.h"

namespace lensrt {

// Tick values covering [lo, hi] at a 1/2/5 x 10^k step giving about `count`.
std::vector<double> niceTicks(double lo, double hi, int count);
// The same range widened outward to the nearest ticks.
void widenToTicks(double& lo, double& hi, int count);

struct PlotAxis {
  double lo = 0.0, hi = 1.0;
  std::string title;  // with units, e.g. "image height (mm)"
  int ticks = 6;
};

class PlotFrame {
 public:
  // The data area's page rectangle: top-left `corner`, size w x h (px).
  PlotFrame(Vec2d corner, double w, double h, PlotAxis x, PlotAxis y);

  Vec2d map(Vec2d data) const;
  // Box, grid lines, ticks, tick labels and axis titles.
  void drawAxes(Svg& svg) const;
  // A data polyline, each point clamped into the frame.
  void series(Svg& svg, const std::vector<Vec2d>& data, const std::string& attributes) const;

  Vec2d corner() const { return corner_; }
  double w() const { return w_; }
  double h() const { return h_; }

 private:
  Vec2d corner_;
  double w_, h_;
  PlotAxis x_, y_;
};

// Styles for plot elements (class names used by PlotFrame and the commands).
std::string plotCss();

}  // namespace lensrt
