#include "report/lens_plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "optics/chromatic.h"
#include "optics/distortion.h"
#include "optics/relative_illumination.h"
#include "optics/spot_diagram.h"
#include "report/svg_plot.h"

namespace lensrt {
namespace {

constexpr double kPageW = 920.0, kPageH = 650.0;

// Title, lens summary and the plotted quantity's definition (two lines).
Svg page(const LensView& view, const std::string& what, const std::string& definition1,
         const std::string& definition2, double height = kPageH) {
  Svg svg(kPageW, height);
  svg.style(plotCss());
  svg.style(R"(.ri { stroke: #1f5fa8; stroke-width: 2.4; }
.vig { stroke: #d9822b; stroke-width: 1.8; stroke-dasharray: 7 4; }
.cos4 { stroke: #777; stroke-width: 1.6; stroke-dasharray: 2 3; }
.dist { stroke: #b0302a; stroke-width: 2.4; }
.zero { stroke: #333; stroke-width: 1; }
.marker { stroke: #8a8a8a; stroke-width: 1; stroke-dasharray: 4 4; }
.markerlabel { font-size: 11px; fill: #666; }
.spot { fill: #1f5fa8; fill-opacity: 0.75; }
.airy { fill: none; stroke: #2a9d4b; stroke-width: 1.2; stroke-dasharray: 5 3; }
.cross { stroke: #999; stroke-width: 0.8; }
.focal { stroke: #6a3d9a; stroke-width: 2.4; }
.lateral { stroke: #b0302a; stroke-width: 2.4; }
)");
  const std::string& name = view.lens.prescription().name;
  svg.text({40, 38}, fmt::format("{} \u2014 {}", name, what), "class=\"title\"");
  svg.text({40, 60}, view.summary(), "class=\"subtitle\"");
  svg.text({40, 80}, definition1, "class=\"note\"");
  svg.text({40, 96}, definition2, "class=\"note\"");
  return svg;
}

// Dashed verticals at the sensor's half height, half width and corner.
void sensorMarkers(Svg& svg, const PlotFrame& frame, const LensView& view, double yTop, double xMax) {
  const struct {
    double x;
    const char* label;
  } marks[] = {{view.sensorHeightMm / 2, "\u00bd height"},
               {view.sensorWidthMm / 2, "\u00bd width"},
               {view.halfDiagonalMm(), "corner"}};
  for (const auto& m : marks) {
    if (m.x > xMax * 1.0001) continue;
    const Vec2d top = frame.map({m.x, yTop});
    svg.line(top, {top.x, frame.corner().y + frame.h()}, "class=\"marker\"");
    svg.text({top.x - 4, frame.corner().y + 14}, m.label, "class=\"markerlabel\" text-anchor=\"end\"");
  }
}

void legendEntry(Svg& svg, Vec2d at, const std::string& cls, const std::string& label) {
  svg.line(at, {at.x + 34, at.y}, "class=\"" + cls + "\"");
  svg.text({at.x + 42, at.y + 4}, label, "class=\"legend\"");
}

}  // namespace

std::string PlotTable::csv() const {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i];
  out += '\n';
  for (const auto& row : rows) {
    for (std::size_t i = 0; i < row.size(); ++i) out += fmt::format("{}{:.9g}", i ? "," : "", row[i]);
    out += '\n';
  }
  return out;
}

LensPlot plotRelativeIllumination(const LensView& view) {
  Svg svg =
      page(view, "relative illumination",
           "RI(r) = E(r) / E(0): film irradiance from a uniform Lambertian scene, i.e. the projected solid "
           "angle \u222b cos\u2074\u03b8 / d\u00b2 dA",
           "of all exactly traced rays from film point r that pass the lens (includes cos\u2074 falloff, "
           "vignetting and pupil aberration).");
  const double maxR = view.halfDiagonalMm();
  const auto curve = relativeIlluminationCurve(view.lens, view.filmDistanceMm, maxR, 45);
  svg.comment(
      "Relative illumination: E(r)/E(0) with E = L * integral over the passing part of the rear-vertex plane "
      "of "
      "cos^4(theta)/d^2 dA (exact rays, includes cos^4 falloff, vignetting and pupil aberration). "
      "Vignetting: passing area / on-axis passing area. cos^4: of the ray to the passing area's centroid.");
  PlotAxis x{0.0, maxR, "image height on the film (mm)", 8};
  widenToTicks(x.lo, x.hi, 8);
  const PlotFrame frame({90, 120}, 760, 410, x, PlotAxis{0.0, 1.1, "relative illumination", 11});
  frame.drawAxes(svg);
  sensorMarkers(svg, frame, view, 1.1, maxR);
  std::vector<Vec2d> ri, vig, cos4;
  PlotTable table{{"film_radius_mm", "relative_illumination", "vignetting", "cos4"}, {}};
  for (const auto& p : curve) {
    table.rows.push_back({p.filmRadiusMm, p.relative, p.areaRatio, p.cos4});
    ri.push_back({p.filmRadiusMm, p.relative});
    vig.push_back({p.filmRadiusMm, p.areaRatio});
    if (p.areaRatio > 0.0) cos4.push_back({p.filmRadiusMm, p.cos4});
  }
  frame.series(svg, cos4, "class=\"cos4\"");
  frame.series(svg, vig, "class=\"vig\"");
  frame.series(svg, ri, "class=\"ri\" id=\"relative-illumination\"");
  const double edge = curve.empty() ? 0.0 : curve.back().relative;
  legendEntry(svg, {90, 600}, "ri", fmt::format("relative illumination ({:.0f}% at the corner)", 100 * edge));
  legendEntry(svg, {430, 600}, "vig", "vignetting: passing pupil area");
  legendEntry(svg, {680, 600}, "cos4", "cos\u2074 of image-side angle");
  svg.text({90, 625},
           fmt::format(
               "d line; film {:.2f} mm behind the rear vertex; cos\u2074 angle measured to the centroid of "
               "the passing area.",
               view.filmDistanceMm),
           "class=\"note\"");
  return {std::move(svg), std::move(table)};
}

LensPlot plotDistortion(const LensView& view) {
  Svg svg =
      page(view, "distortion",
           "D = 100 (y_real \u2212 y_paraxial) / y_paraxial: the real chief ray (through the stop centre) "
           "against the paraxial image height",
           "y_paraxial = f tan\u03b8 (object at infinity) or |m| D tan\u03b8 (object at D); negative = "
           "barrel, positive = pincushion.");
  svg.comment(
      "Distortion: percent of the real chief ray's image height against the paraxial one (f tan theta "
      "at infinity, |m| D tan theta for an object at distance D), on the focused film plane.");
  const auto curve = distortionCurve(view.lens, view.focusMm, view.filmDistanceMm, view.halfDiagonalMm(), 61);
  double maxH = 1e-3, lo = 0.0, hi = 0.0;
  for (const auto& d : curve) {
    maxH = std::max(maxH, d.realHeightMm);
    lo = std::min(lo, d.percent);
    hi = std::max(hi, d.percent);
  }
  if (hi - lo < 0.2) {  // an almost distortion-free lens: show +-0.1 % at least
    lo = std::min(lo, -0.1);
    hi = std::max(hi, 0.1);
  }
  PlotAxis x{0.0, std::max(maxH, view.halfDiagonalMm()), "real image height on the film (mm)", 8};
  widenToTicks(x.lo, x.hi, 8);
  PlotAxis y{lo, hi, "distortion (%)", 8};
  widenToTicks(y.lo, y.hi, 8);
  const PlotFrame frame({90, 120}, 760, 410, x, y);
  frame.drawAxes(svg);
  sensorMarkers(svg, frame, view, y.hi, x.hi);
  svg.line(frame.map({x.lo, 0.0}), frame.map({x.hi, 0.0}), "class=\"zero\"");
  std::vector<Vec2d> pts;
  PlotTable table{{"field_angle_deg", "real_height_mm", "paraxial_height_mm", "distortion_percent"}, {}};
  for (const auto& d : curve) {
    pts.push_back({d.realHeightMm, d.percent});
    table.rows.push_back({d.fieldAngleDeg, d.realHeightMm, d.paraxialHeightMm, d.percent});
  }
  frame.series(svg, pts, "class=\"dist\" id=\"distortion\"");
  if (!curve.empty()) {
    const auto& last = curve.back();
    const Vec2d end = frame.map({last.realHeightMm, last.percent});
    svg.circle(end, 3.5, "fill=\"#b0302a\"");
    const bool above = last.percent < 0.5 * (y.lo + y.hi);
    svg.text({end.x - 6, end.y + (above ? -10 : 20)},
             fmt::format("{:.2f}% at {:.1f}\u00b0 field, {:.2f} mm", last.percent, last.fieldAngleDeg,
                         last.realHeightMm),
             "class=\"legend\" text-anchor=\"end\"");
    if (last.realHeightMm < view.halfDiagonalMm() * 0.999)
      svg.text({90, 610},
               "The chief ray is blocked beyond this field: the image circle is smaller than the sensor.",
               "class=\"note\"");
  }
  return {std::move(svg), std::move(table)};
}

LensPlot plotSpotDiagrams(const LensView& view) {
  Svg svg =
      page(view, "spot diagrams",
           "Film intersections of a uniform grid of rays over the passing beam, for fields whose chief rays "
           "land at 0, \u00bd and 1 \u00d7",
           "the sensor's half-diagonal; object at the focus distance, d line, RMS radius about the centroid. "
           "Film x is the meridional direction.",
           560.0);
  svg.comment(
      "Spot diagrams: uniform grid over the passing entrance beam, d-line, film at the focused position.");
  const FieldLimit limit =
      fieldForImageHeight(view.lens, view.focusMm, view.filmDistanceMm, view.halfDiagonalMm());
  const double fractions[] = {0.0, 0.5, 1.0};
  std::vector<SpotDiagram> spots;
  std::vector<double> heights;
  for (const double f : fractions) {
    const double h = f * limit.imageHeightMm;
    const double angle =
        f == 1.0 ? limit.angleDeg
                 : fieldAngleForImageHeight(view.lens, view.focusMm, view.filmDistanceMm, h).value_or(0.0);
    spots.push_back(spotDiagram(view.lens, {angle, view.focusMm}, view.filmDistanceMm, 41));
    heights.push_back(h);
  }
  const double airyUm = 1.22 * 587.56e-3 * view.lens.paraxial().fNumber;
  double extent = airyUm;
  for (const auto& s : spots) extent = std::max(extent, s.maxRadiusMm * 1000.0);
  double lo = -extent * 1.05, hi = extent * 1.05;
  widenToTicks(lo, hi, 4);
  const double half = std::max(-lo, hi);
  const double size = 230.0, gap = 50.0, left = 90.0, top = 150.0;
  PlotTable table{{"field_angle_deg", "image_height_mm", "dx_um", "dy_um"}, {}};
  for (std::size_t i = 0; i < spots.size(); ++i) {
    const SpotDiagram& s = spots[i];
    for (const Vec2d& p : s.points) {
      const Vec2d d = (p - s.centroid) * 1000.0;
      table.rows.push_back({s.field.angleDeg, heights[i], d.x, d.y});
    }
    const PlotFrame frame({left + i * (size + gap), top}, size, size,
                          PlotAxis{-half, half, "x \u2212 centroid (\u00b5m)", 4},
                          PlotAxis{-half, half, i == 0 ? "y \u2212 centroid (\u00b5m)" : "", 4});
    frame.drawAxes(svg);
    svg.line(frame.map({-half, 0}), frame.map({half, 0}), "class=\"cross\"");
    svg.line(frame.map({0, -half}), frame.map({0, half}), "class=\"cross\"");
    svg.circle(frame.map({0, 0}), airyUm / (2 * half) * size, "class=\"airy\"");
    svg.beginGroup(fmt::format("class=\"spot\" id=\"spot-{}\"", i));
    for (const Vec2d& p : s.points) {
      const Vec2d d = (p - s.centroid) * 1000.0;
      if (std::abs(d.x) > half || std::abs(d.y) > half) continue;
      svg.circle(frame.map(d), 1.1, "");
    }
    svg.endGroup();
    const double cx = left + i * (size + gap) + size / 2;
    svg.text({cx, top - 26},
             fmt::format("field {:.2f}\u00b0, image height {:.2f} mm", s.field.angleDeg, heights[i]),
             "class=\"legend\" text-anchor=\"middle\"");
    svg.text({cx, top - 9},
             s.points.empty() ? std::string("no ray passes")
                              : fmt::format("RMS radius {:.1f} \u00b5m  ({} rays)", s.rmsRadiusMm * 1000.0,
                                            s.points.size()),
             "class=\"legend rms\" text-anchor=\"middle\" font-weight=\"bold\"");
  }
  svg.line({left, top + size + 80}, {left + 30, top + size + 80}, "class=\"airy\"");
  svg.text({left + 38, top + size + 84},
           fmt::format("Airy disc radius 1.22 \u03bb N = {:.1f} \u00b5m (\u03bb = 587.6 nm, N = {:.3g})",
                       airyUm, view.lens.paraxial().fNumber),
           "class=\"note\"");
  if (!limit.reachedTarget)
    svg.text({left, top + size + 104},
             fmt::format(
                 "Full field is the widest traceable chief ray ({:.1f}\u00b0, {:.2f} mm): the image circle "
                 "is smaller than the sensor diagonal.",
                 limit.angleDeg, limit.imageHeightMm),
             "class=\"note\"");
  return {std::move(svg), std::move(table)};
}

LensPlot plotChromatic(const LensView& view) {
  Svg svg = page(view, "chromatic aberration",
                 "Left: axial colour, the paraxial back focal length at each wavelength minus that at the d "
                 "line (587.6 nm); glass index from n_d, V_d (or Sellmeier).",
                 "Right: lateral colour, the chief ray's image height at F (486.1 nm) minus at C (656.3 nm), "
                 "against the d-line image height; object at infinity.");
  svg.comment(
      "Chromatic aberration: focal shift = paraxial BFL(lambda) - BFL(d line), mm; lateral colour = exact "
      "chief-ray image height at F minus at C on the d line's paraxial focal plane, um.");
  const int points = 41;
  const ChromaticCurves c = chromaticCurves(view.lens, view.halfDiagonalMm(), points);
  PlotTable table{{"wavelength_nm", "focal_shift_mm", "image_height_mm", "lateral_color_um"}, {}};
  std::vector<Vec2d> focal, lateral;
  double fLo = 0.0, fHi = 0.0, lLo = 0.0, lHi = 0.0;
  for (int i = 0; i < points; ++i) {
    table.rows.push_back({c.wavelengthNm[i], c.focalShiftMm[i], c.imageHeightMm[i], c.lateralColorUm[i]});
    focal.push_back({c.wavelengthNm[i], c.focalShiftMm[i]});
    fLo = std::min(fLo, c.focalShiftMm[i]), fHi = std::max(fHi, c.focalShiftMm[i]);
    if (std::isnan(c.lateralColorUm[i])) continue;
    lateral.push_back({c.imageHeightMm[i], c.lateralColorUm[i]});
    lLo = std::min(lLo, c.lateralColorUm[i]), lHi = std::max(lHi, c.lateralColorUm[i]);
  }
  // A lens without dispersion data: flat zero lines on a small scale.
  if (fHi - fLo < 1e-3) fLo = std::min(fLo, -0.01), fHi = std::max(fHi, 0.01);
  if (lHi - lLo < 1e-2) lLo = std::min(lLo, -1.0), lHi = std::max(lHi, 1.0);
  PlotAxis fx{c.wavelengthNm.front(), c.wavelengthNm.back(), "wavelength (nm)", 6};
  PlotAxis fy{fLo, fHi, "focal shift from the d line (mm)", 8};
  widenToTicks(fy.lo, fy.hi, 8);
  const PlotFrame left({90, 130}, 340, 400, fx, fy);
  left.drawAxes(svg);
  left.series(svg, {{fx.lo, 0.0}, {fx.hi, 0.0}}, "class=\"zero\"");
  left.series(svg, focal, "class=\"focal\" id=\"focal-shift\"");
  PlotAxis lx{0.0, view.halfDiagonalMm(), "image height on the film (mm)", 6};
  widenToTicks(lx.lo, lx.hi, 6);
  PlotAxis ly{lLo, lHi, "lateral colour F \u2212 C (\u00b5m)", 8};
  widenToTicks(ly.lo, ly.hi, 8);
  const PlotFrame right({540, 130}, 340, 400, lx, ly);
  right.drawAxes(svg);
  sensorMarkers(svg, right, view, ly.hi, lx.hi);
  right.series(svg, {{lx.lo, 0.0}, {lx.hi, 0.0}}, "class=\"zero\"");
  right.series(svg, lateral, "class=\"lateral\" id=\"lateral-color\"");
  const std::optional<LateralColor> corner = lateralColor(view.lens, view.halfDiagonalMm());
  svg.text({90, 600},
           hasDispersion(view.lens.prescription())
               ? fmt::format("axial colour (BFL at C minus F) {:.4f} mm; lateral colour at the corner {}",
                             axialColorMm(view.lens.prescription()),
                             corner ? fmt::format("{:.2f} \u00b5m", corner->um()) : std::string("n/a"))
               : std::string("No dispersion data (no Abbe numbers or Sellmeier coefficients): every "
                             "wavelength focuses alike."),
           "class=\"legend\"");
  return {std::move(svg), std::move(table)};
}

}  // namespace lensrt
