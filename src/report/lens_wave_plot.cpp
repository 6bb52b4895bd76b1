#include "report/lens_wave_plot.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "report/svg_plot.h"

namespace lensrt {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

Svg wavePage(const LensWave& wave, const Psf& psf, const std::string& what, const std::string& definition) {
  Svg svg(920.0, 600.0);
  svg.style(plotCss());
  svg.style(R"(.psfx { stroke: #1f5fa8; stroke-width: 2.2; }
.psfy { stroke: #b0302a; stroke-width: 1.8; stroke-dasharray: 7 4; }
.limit { stroke: #777; stroke-width: 1.4; stroke-dasharray: 2 3; }
)");
  svg.text({40, 38}, fmt::format("{} \u2014 {}", wave.view.lens.prescription().name, what),
           "class=\"title\"");
  svg.text({40, 60}, wave.summary(), "class=\"subtitle\"");
  svg.text({40, 80}, definition, "class=\"note\"");
  std::string lines;
  for (const PsfWavelength& w : psf.wavelengths)
    lines += fmt::format("{}{:.1f} nm \u00d7{:.2f}: W_rms {:.3f} waves, Strehl {:.3f}",
                         lines.empty() ? "" : "; ", w.wavelengthNm, w.weight, w.rmsWaves, w.strehl);
  svg.text({40, 96}, lines, "class=\"note\"");
  svg.text({40, 585}, samplingText(psf), "class=\"note\"");
  return svg;
}

void legend(Svg& svg, Vec2d at, const std::string& cls, const std::string& label) {
  svg.line(at, {at.x + 30, at.y}, "class=\"" + cls + "\"");
  svg.text({at.x + 36, at.y + 4}, label, "class=\"legend\"");
}

}  // namespace

LensPlot plotPsf(const LensWave& wave, const Psf& psf) {
  Svg svg =
      wavePage(wave, psf, "point spread function",
               "FFT of the pupil function (exact rays, OPD against the reference sphere on the chief ray's "
               "image); film x is the meridional direction.");
  // Out to 4 Airy radii of the longest wavelength or 3 RMS radii, whichever is wider.
  double longest = 0.0;
  for (const PsfWavelength& w : psf.wavelengths) longest = std::max(longest, w.wavelengthNm);
  const double airy = 1.22 * longest * 1e-6 * wave.fNumber;
  const double reach = std::min(
      std::max(4.0 * airy, 3.0 * psf.rmsRadiusMm() + std::hypot(psf.centroidMm().x, psf.centroidMm().y)),
      0.45 * psf.size * psf.pixelMm);
  const int steps = std::max(2, int(std::ceil(reach / psf.pixelMm)));
  const int c = psf.size / 2;
  double peak = 0.0;
  for (const double v : psf.limit) peak = std::max(peak, v);
  PlotTable table{
      {"offset_um", "psf_x", "psf_y", "limit_x", "limit_y", "encircled_energy", "limit_encircled_energy"},
      {}};
  std::vector<Vec2d> px, py, lx, ee, lee;
  std::vector<double> radii;
  for (int k = 0; k <= steps; ++k) radii.push_back(k * psf.pixelMm);
  const std::vector<double> energy = encircledEnergy(psf, radii),
                            limitEnergy = encircledEnergy(psf, radii, {}, true);
  for (int k = -steps; k <= steps; ++k) {
    const double um = k * psf.pixelMm * 1000.0;
    const auto value = [&](const std::vector<double>& v, int i, int j) {
      return v[std::size_t(j) * std::size_t(psf.size) + std::size_t(i)] / peak;
    };
    const double x = value(psf.intensity, c + k, c), y = value(psf.intensity, c, c + k);
    const double lxv = value(psf.limit, c + k, c), lyv = value(psf.limit, c, c + k);
    double e = kNan, le = kNan;
    if (k >= 0) {
      e = energy[std::size_t(k)];
      le = limitEnergy[std::size_t(k)];
      ee.push_back({um, e});
      lee.push_back({um, le});
    }
    table.rows.push_back({um, x, y, lxv, lyv, e, le});
    px.push_back({um, x});
    py.push_back({um, y});
    lx.push_back({um, lxv});
  }
  PlotAxis xAxis{-reach * 1000.0, reach * 1000.0, "film offset from the chief ray's image (\u00b5m)", 6};
  widenToTicks(xAxis.lo, xAxis.hi, 6);
  const PlotFrame left({80, 130}, 360, 360, xAxis,
                       PlotAxis{0.0, 1.0, "intensity / diffraction-limited peak", 6});
  left.drawAxes(svg);
  left.series(svg, lx, "class=\"limit\"");
  left.series(svg, py, "class=\"psfy\"");
  left.series(svg, px, "class=\"psfx\" id=\"psf-x\"");
  PlotAxis rAxis{0.0, reach * 1000.0, "radius about the chief ray's image (\u00b5m)", 6};
  widenToTicks(rAxis.lo, rAxis.hi, 6);
  const PlotFrame right({530, 130}, 360, 360, rAxis, PlotAxis{0.0, 1.0, "encircled energy", 6});
  right.drawAxes(svg);
  right.series(svg, lee, "class=\"limit\"");
  right.series(svg, ee, "class=\"psfx\" id=\"encircled-energy\"");
  legend(svg, {80, 540}, "psfx", "along film x (meridional)");
  legend(svg, {300, 540}, "psfy", "along film y (sagittal)");
  legend(svg, {500, 540}, "limit",
         fmt::format("diffraction limit (polychromatic Strehl {:.3f})", psf.strehl));
  return {std::move(svg), std::move(table)};
}

LensPlot plotMtf(const LensWave& wave, const Psf& psf, const MtfCurves& mtf, const ThroughFocusMtf& focus) {
  Svg svg =
      wavePage(wave, psf, "MTF",
               "|FFT of the PSF|: tangential = frequencies along film x (the field's meridian), sagittal = "
               "along y; through focus at one frequency.");
  const double maxF = mtf.frequencyPerMm.empty() ? 1.0 : mtf.frequencyPerMm.back();
  PlotAxis fAxis{0.0, maxF, "spatial frequency (cycles/mm)", 6};
  const PlotFrame left({80, 130}, 360, 360, fAxis, PlotAxis{0.0, 1.0, "MTF", 6});
  left.drawAxes(svg);
  std::vector<Vec2d> t, s, lt, ls;
  for (std::size_t k = 0; k < mtf.frequencyPerMm.size(); ++k) {
    const double f = mtf.frequencyPerMm[k];
    t.push_back({f, mtf.tangential[k]});
    s.push_back({f, mtf.sagittal[k]});
    lt.push_back({f, mtf.limitTangential[k]});
    ls.push_back({f, mtf.limitSagittal[k]});
  }
  left.series(svg, lt, "class=\"limit\"");
  left.series(svg, ls, "class=\"limit\"");
  left.series(svg, s, "class=\"psfy\" id=\"sagittal\"");
  left.series(svg, t, "class=\"psfx\" id=\"tangential\"");
  double lo = 0.0, hi = 1.0;
  if (!focus.filmShiftMm.empty())
    lo = focus.filmShiftMm.front() * 1000.0, hi = focus.filmShiftMm.back() * 1000.0;
  PlotAxis zAxis{lo, hi, fmt::format("film shift (\u00b5m) at {:g} cycles/mm", focus.frequencyPerMm), 6};
  const PlotFrame right({530, 130}, 360, 360, zAxis, PlotAxis{0.0, 1.0, "MTF through focus", 6});
  right.drawAxes(svg);
  std::vector<Vec2d> ft, fs, fl;
  for (std::size_t k = 0; k < focus.filmShiftMm.size(); ++k) {
    const double z = focus.filmShiftMm[k] * 1000.0;
    ft.push_back({z, focus.tangential[k]});
    fs.push_back({z, focus.sagittal[k]});
    fl.push_back({z, focus.limit[k]});
  }
  right.series(svg, fl, "class=\"limit\"");
  right.series(svg, fs, "class=\"psfy\"");
  right.series(svg, ft, "class=\"psfx\" id=\"through-focus\"");
  legend(svg, {80, 540}, "psfx", "tangential");
  legend(svg, {260, 540}, "psfy", "sagittal");
  legend(svg, {440, 540}, "limit", "diffraction limit of the same pupil");
  PlotTable table{
      {"frequency_per_mm", "tangential", "sagittal", "limit_tangential", "limit_sagittal", "film_shift_um",
       "through_focus_tangential", "through_focus_sagittal", "through_focus_limit"},
      {}};
  const std::size_t rows = std::max(mtf.frequencyPerMm.size(), focus.filmShiftMm.size());
  for (std::size_t k = 0; k < rows; ++k) {
    const bool a = k < mtf.frequencyPerMm.size(), b = k < focus.filmShiftMm.size();
    table.rows.push_back({a ? mtf.frequencyPerMm[k] : kNan, a ? mtf.tangential[k] : kNan,
                          a ? mtf.sagittal[k] : kNan, a ? mtf.limitTangential[k] : kNan,
                          a ? mtf.limitSagittal[k] : kNan, b ? focus.filmShiftMm[k] * 1000.0 : kNan,
                          b ? focus.tangential[k] : kNan, b ? focus.sagittal[k] : kNan,
                          b ? focus.limit[k] : kNan});
  }
  return {std::move(svg), std::move(table)};
}

}  // namespace lensrt
