#include "report/response_plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <filesystem>

#include "report/svg_plot.h"

namespace lensrt {

Svg plotSensorResponse(const SensorResponse& response) {
  Svg svg(920.0, 600.0);
  svg.style(plotCss());
  svg.style(R"(.r { stroke: #c62828; stroke-width: 2.4; }
.g { stroke: #2e7d32; stroke-width: 2.4; }
.b { stroke: #1f5fa8; stroke-width: 2.4; }
)");
  const std::string camera = response.maker.empty() && response.model.empty()
                                 ? ""
                                 : fmt::format("{} {}", response.maker, response.model);
  const std::string what = response.cie1931 ? "colour matching functions" : "spectral sensitivity";
  // The name (a file's without its folders) in the title only when there is
  // no camera to name; the name or path and the source below.
  const std::string shortName = std::filesystem::path(response.name).filename().string();
  svg.text({40, 38}, fmt::format("{} \u2014 {}", camera.empty() ? shortName : camera, what),
           "class=\"title\"");
  svg.text(
      {40, 60},
      response.source.empty() ? response.name : fmt::format("{} \u00b7 {}", response.name, response.source),
      "class=\"subtitle\"");

  double largest = 0.0;
  for (const Vec3d& v : response.rgb) largest = std::max({largest, v.x, v.y, v.z});
  const std::array<const char*, 3> channel = response.cie1931
                                                 ? std::array<const char*, 3>{"x\u0304", "y\u0304", "z\u0304"}
                                                 : std::array<const char*, 3>{"r", "g", "b"};
  svg.text({40, 80},
           fmt::format("Relative to the largest value of the three ({:.4g}); linear between the {} tabulated "
                       "wavelengths, 0 outside them.",
                       largest, response.wavelengthsNm.size()),
           "class=\"note\"");

  const bool empty = response.wavelengthsNm.empty();
  PlotAxis x{empty ? 360.0 : response.wavelengthsNm.front(), empty ? 830.0 : response.wavelengthsNm.back(),
             "wavelength (nm)", 8};
  widenToTicks(x.lo, x.hi, 8);
  const PlotFrame frame({90, 100}, 760, 400, x, PlotAxis{0.0, 1.1, "relative response", 11});
  frame.drawAxes(svg);
  const Vec3d peak = response.peakWavelengthsNm();
  const char* const classes[] = {"r", "g", "b"};
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<Vec2d> curve;
    for (std::size_t i = 0; i < response.rgb.size(); ++i)
      curve.push_back({response.wavelengthsNm[i], largest > 0.0 ? response.rgb[i][c] / largest : 0.0});
    frame.series(svg, curve, fmt::format("class=\"{}\" id=\"curve-{}\"", classes[c], classes[c]));
    const Vec2d at{90.0 + 250.0 * double(c), 560.0};
    svg.line(at, {at.x + 34, at.y}, fmt::format("class=\"{}\"", classes[c]));
    svg.text({at.x + 42, at.y + 4}, fmt::format("{} (peak {:g} nm)", channel[c], peak[c]),
             "class=\"legend\"");
  }
  return svg;
}

}  // namespace lensrt
