#include "report/lens_diagram.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <vector>

#include "core/constants.h"
#include "optics/distortion.h"

namespace lensrt {
namespace {

constexpr double kPageW = 1200.0;
constexpr double kMaxDrawingH = 500.0;  // px; the page height follows the drawing

// Lens space (z, x in mm) to page pixels: z to the right, +x up.
struct PageMap {
  double scale = 1.0;  // px per mm
  double z0 = 0.0;     // z at the left edge of the drawing area
  double left = 0.0, axisY = 0.0;
  Vec2d operator()(double z, double x) const { return {left + (z - z0) * scale, axisY - x * scale}; }
};

struct FieldFan {
  FieldPoint field;
  double imageHeightMm = 0.0;
  const char* colour;
  std::string label;
};

// A ray's drawn polyline: from the left edge (or where it enters the
// drawing) through every surface hit to the film, or to where it is blocked.
struct DrawnRay {
  std::vector<Vec3d> points;
  bool passed = false;
};

DrawnRay traceRay(const LensSystem& lens, const FieldPoint& field, double aimX, double zLeft, double xMax,
                  double filmZ) {
  DrawnRay drawn;
  const LensRay ray = fieldRay(lens, field, {aimX, 0.0});
  // Start at the drawing's left edge, or where the ray enters its top/bottom.
  double t = (zLeft - ray.origin.z) / ray.direction.z;
  Vec3d start = ray.origin + ray.direction * t;
  if (std::abs(start.x) > xMax && ray.direction.x != 0.0) {
    const double tx = (std::copysign(xMax, start.x) - ray.origin.x) / ray.direction.x;
    if (tx > t) start = ray.origin + ray.direction * tx;
  }
  drawn.points.push_back(start);
  std::vector<Vec3d> path;
  const auto out = lens.traceFromScene(ray, kWavelengthDNm, &path);
  drawn.points.insert(drawn.points.end(), path.begin(), path.end());
  const auto& surfaces = lens.prescription().surfaces;
  if (out) {
    drawn.passed = true;
    const double tf = (filmZ - out->origin.z) / out->direction.z;
    drawn.points.push_back(out->origin + out->direction * tf);
    return drawn;
  }
  // Blocked at surface k: continue the last segment to that surface's rim
  // plane (the stop's own plane for the diaphragm), where the ray stops.
  const int k = static_cast<int>(path.size());
  if (k >= lens.surfaceCount()) return drawn;
  Vec3d d = path.empty() ? ray.direction : normalize(path.back() - drawn.points[drawn.points.size() - 2]);
  if (k > 0) {
    const Surface& s = surfaces[k - 1];
    const double n1 = k >= 2 ? surfaces[k - 2].medium.nd : 1.0, n2 = s.medium.nd;
    if (!s.isStop && n1 != n2) {
      const Vec3d hit = path.back();
      Vec3d normal =
          s.isAspheric()    ? asphereNormal(s.profile(), Vec3d{hit.x, hit.y, hit.z - lens.surfaceZ(k - 1)})
          : s.radius == 0.0 ? Vec3d{0, 0, -1}
                            : normalize(Vec3d{hit.x, hit.y, hit.z - (lens.surfaceZ(k - 1) + s.radius)});
      if (dot(normal, d) > 0.0) normal = -normal;
      if (!refract(d, normal, n1, n2, d)) return drawn;  // total internal reflection: it ends here
    }
  }
  const Surface& blocker = surfaces[k];
  const double rimZ = lens.surfaceZ(k) + blocker.sag(blocker.apertureDiameter / 2.0);
  const Vec3d from = drawn.points.back();
  if (d.z > 1e-9) {
    const double tb = std::max(0.0, (rimZ - from.z) / d.z);
    drawn.points.push_back(from + d * tb);
  }
  return drawn;
}

// Rays that would enter the drawing only after their first surface (steep
// rays blocked outside it) are not drawn at all.
DrawnRay traceForDrawing(const LensSystem& lens, const FieldPoint& field, double aimX, double zLeft,
                         double xMax, double filmZ) {
  DrawnRay drawn = traceRay(lens, field, aimX, zLeft, xMax, filmZ);
  if (drawn.points.size() < 2 || drawn.points[0].z > drawn.points[1].z) drawn.points.clear();
  return drawn;
}

constexpr const char* kGhostColour = "#e91e63";

double niceLength(double target) {
  const double mag = std::pow(10.0, std::floor(std::log10(target)));
  for (const double m : {5.0, 2.0, 1.0})
    if (m * mag <= target) return m * mag;
  return mag;
}

}  // namespace

Svg drawLensDiagram(const LensView& view, const std::optional<DiagramGhost>& ghost) {
  const LensSystem& lens = view.lens;
  const LensPrescription& rx = lens.prescription();
  const ParaxialData& p = lens.paraxial();
  const double filmZ = view.filmZ();

  // Fields whose real chief rays land at 0, 1/2 and 1 x the half-diagonal
  // (or the widest traceable field when the image circle is smaller).
  const FieldLimit full = fieldForImageHeight(lens, view.focusMm, view.filmDistanceMm, view.halfDiagonalMm());
  const double halfAngle =
      fieldAngleForImageHeight(lens, view.focusMm, view.filmDistanceMm, full.imageHeightMm / 2).value_or(0.0);
  std::vector<FieldFan> fans = {{{0.0, view.focusMm}, 0.0, "#1f5fa8", "on axis"},
                                {{halfAngle, view.focusMm}, full.imageHeightMm / 2, "#2a9d4b", ""},
                                {{full.angleDeg, view.focusMm}, full.imageHeightMm, "#c0392b", ""}};
  fans[1].label =
      fmt::format("{:.1f}\u00b0: half field, image height {:.2f} mm", halfAngle, fans[1].imageHeightMm);
  fans[2].label =
      fmt::format("{:.1f}\u00b0: full field, image height {:.2f} mm ({})", full.angleDeg, full.imageHeightMm,
                  full.reachedTarget ? "sensor corner" : "edge of the image circle");

  // Extents in lens space: the glass, the film, and the cardinal points
  // unless they lie absurdly far away.
  double aMax = 0.0;
  for (const Surface& s : rx.surfaces) aMax = std::max(aMax, s.apertureDiameter / 2.0);
  const double zFront = std::min(0.0, rx.surfaces.front().sag(rx.surfaces.front().apertureDiameter / 2));
  const double length = filmZ - zFront;
  double zLo = zFront - 0.3 * length, zHi = filmZ + 0.06 * length;
  for (const double z : {p.frontPrincipalZ, p.rearPrincipalZ, p.rearFocalZ, p.entrancePupilZ, p.exitPupilZ})
    if (z > zFront - 1.5 * length && z < filmZ + 1.0 * length) {
      zLo = std::min(zLo, z - 0.05 * length);
      zHi = std::max(zHi, z + 0.05 * length);
    }
  const double xMax =
      1.12 * std::max({aMax, view.halfDiagonalMm(), p.entrancePupilDiameter / 2, p.exitPupilDiameter / 2});
  const double drawLeft = 50, drawRight = kPageW - 50, drawTop = 125;
  PageMap map;
  map.scale = std::min((drawRight - drawLeft) / (zHi - zLo), kMaxDrawingH / (2 * xMax));
  const double drawBottom = drawTop + std::max(2 * xMax * map.scale, 260.0);
  const double kPageH = drawBottom + 150;
  map.z0 = zLo;
  map.left = drawLeft + 0.5 * ((drawRight - drawLeft) - (zHi - zLo) * map.scale);
  map.axisY = 0.5 * (drawTop + drawBottom);

  Svg svg(kPageW, kPageH);
  svg.style(R"(text { fill: #222; }
.title { font-size: 22px; font-weight: bold; }
.subtitle { font-size: 14px; fill: #444; }
.note { font-size: 12px; fill: #555; }
.label { font-size: 13px; paint-order: stroke; stroke: white; stroke-width: 3px; stroke-linejoin: round; }
.small { font-size: 11px; fill: #444; }
.element { fill: #d4dee8; stroke: #2c3e50; stroke-width: 1.3; stroke-linejoin: round; }
.axis { stroke: #555; stroke-width: 0.9; stroke-dasharray: 14 4 2 4; }
.stop { stroke: #111; stroke-width: 3.5; stroke-linecap: butt; }
.film { stroke: #111; stroke-width: 3; }
.plane { stroke: #7d3c98; stroke-width: 1; stroke-dasharray: 5 3; }
.pupil { stroke: #7d3c98; stroke-width: 3; }
.point { fill: #7d3c98; }
.ray { fill: none; stroke-width: 0.9; stroke-opacity: 0.9; }
.chief { fill: none; stroke-width: 1.6; }
.blocked { fill: none; stroke-width: 0.8; stroke-dasharray: 3 2; stroke-opacity: 0.8; }
.scalebar { stroke: #111; stroke-width: 2; }
)");
  svg.comment(fmt::format(
      "lens {} ({}); lens space: z along the axis (right = toward the film), x up; scale {:.4g} px/mm",
      rx.name, rx.file, map.scale));
  svg.text(
      {40, 42},
      fmt::format("{} \u2014 EFL {:.2f} mm, f/{:.3g}, focus {}", rx.name, p.efl, p.fNumber, view.focusText()),
      "class=\"title\"");
  svg.text({40, 66}, rx.description.empty() ? rx.file : rx.description, "class=\"subtitle\"");
  if (!rx.source.empty()) svg.text({40, 104}, "Source: " + rx.source, "class=\"note\"");
  svg.text({40, 86},
           fmt::format("Sensor {:g} \u00d7 {:g} mm, film {:.2f} mm behind the last vertex; widest aperture "
                       "f/{:.3g}; d line (587.6 nm); meridional section to scale.",
                       view.sensorWidthMm, view.sensorHeightMm, view.filmDistanceMm, view.widestFNumber),
           "class=\"note\"");

  // Optical axis.
  svg.line(map(zLo, 0), map(zHi, 0), "class=\"axis\"");

  // Glass elements: the front and back surface profiles over their clear
  // apertures, joined by a flat step to the larger aperture and a flat edge.
  svg.beginGroup("id=\"elements\"");
  for (int i = 0; i + 1 < static_cast<int>(rx.surfaces.size()); ++i) {
    const Surface& f = rx.surfaces[i];
    if (f.medium.isAir()) continue;
    const Surface& b = rx.surfaces[i + 1];
    const double zf = lens.surfaceZ(i), zb = lens.surfaceZ(i + 1);
    const double af = f.apertureDiameter / 2, ab = b.apertureDiameter / 2, edge = std::max(af, ab);
    std::vector<Vec2d> outline;
    const int n = 48;
    if (af < edge) outline.push_back(map(zf + f.sag(af), edge));
    for (int k = 0; k <= n; ++k) {
      const double rho = af - 2.0 * af * k / n;
      outline.push_back(map(zf + f.sag(rho), rho));
    }
    if (af < edge) outline.push_back(map(zf + f.sag(af), -edge));
    if (ab < edge) outline.push_back(map(zb + b.sag(ab), -edge));
    for (int k = 0; k <= n; ++k) {
      const double rho = -ab + 2.0 * ab * k / n;
      outline.push_back(map(zb + b.sag(rho), rho));
    }
    if (ab < edge) outline.push_back(map(zb + b.sag(ab), edge));
    svg.polygon(outline, fmt::format("class=\"element\" data-surfaces=\"{} {}\" data-nd=\"{:g}\"", i + 1,
                                     i + 2, f.medium.nd));
  }
  svg.endGroup();

  // The aperture stop as a diaphragm: blades from its opening outward.
  {
    const double zs = p.stopZ, as = rx.surfaces[p.stopIndex].apertureDiameter / 2;
    // Blades reach out to the barrel: the wider of the neighbouring apertures.
    double barrel = as * 1.2 + 0.04 * xMax;
    for (const int k : {p.stopIndex - 1, p.stopIndex + 1})
      if (k >= 0 && k < static_cast<int>(rx.surfaces.size()))
        barrel = std::max(barrel, rx.surfaces[k].apertureDiameter / 2 * 1.05);
    const double outer = barrel;
    svg.beginGroup("id=\"stop\"");
    for (const double sgn : {1.0, -1.0}) {
      svg.line(map(zs, sgn * as), map(zs, sgn * outer), "class=\"stop\"");
      const Vec2d tip = map(zs, sgn * as);
      svg.line({tip.x - 4, tip.y}, {tip.x + 4, tip.y}, "class=\"stop\" stroke-width=\"2\"");
    }
    svg.endGroup();
    svg.text(Vec2d{map(zs, outer).x, map(zs, outer).y - 8}, fmt::format("stop \u2300{:.1f}", 2 * as),
             "class=\"label\" text-anchor=\"middle\"");
  }

  // Ray fans, drawn before the marks so labels stay readable.
  svg.beginGroup("id=\"rays\"");
  for (const FieldFan& fan : fans) {
    const auto band = meridionalPassBand(lens, fan.field);
    if (!band) continue;
    const double w = band->hi - band->lo;
    std::vector<double> aims;
    const int count = 9;
    for (int k = 0; k < count; ++k) aims.push_back(band->lo + w * (0.002 + 0.996 * k / (count - 1)));
    const auto chief = chiefRayAim(lens, fan.field);
    svg.beginGroup(fmt::format("class=\"fan\" stroke=\"{}\"", fan.colour));
    for (const double aim : aims) {
      const DrawnRay r = traceForDrawing(lens, fan.field, aim, zLo, xMax, filmZ);
      if (r.points.empty()) continue;
      std::vector<Vec2d> pts;
      for (const Vec3d& q : r.points) pts.push_back(map(q.z, q.x));
      svg.polyline(pts, "class=\"ray\"");
    }
    if (chief) {
      const DrawnRay r = traceForDrawing(lens, fan.field, *chief, zLo, xMax, filmZ);
      std::vector<Vec2d> pts;
      for (const Vec3d& q : r.points) pts.push_back(map(q.z, q.x));
      if (!pts.empty()) svg.polyline(pts, "class=\"chief\"");
    }
    // Just outside the passing band on each side: blocked, drawn to where they stop.
    for (const double aim : {band->lo - 0.06 * w - 1e-3, band->hi + 0.06 * w + 1e-3}) {
      const DrawnRay r = traceForDrawing(lens, fan.field, aim, zLo, xMax, filmZ);
      if (r.passed || r.points.size() < 2) continue;
      std::vector<Vec2d> pts;
      for (const Vec3d& q : r.points) pts.push_back(map(q.z, q.x));
      svg.polyline(pts, "class=\"blocked\"");
      const Vec2d end = pts.back();
      svg.line({end.x - 3, end.y - 3}, {end.x + 3, end.y + 3}, "class=\"blocked\" stroke-dasharray=\"none\"");
      svg.line({end.x - 3, end.y + 3}, {end.x + 3, end.y - 3}, "class=\"blocked\" stroke-dasharray=\"none\"");
    }
    svg.endGroup();
  }
  svg.endGroup();

  // The ghost: an axial bundle from infinity across the front element, the
  // rays the apertures let through drawn to the film.
  if (ghost) {
    svg.beginGroup(fmt::format("class=\"ghost\" stroke=\"{}\"", kGhostColour));
    const double front = lens.frontApertureRadius();
    const int count = 15;
    for (int k = 0; k < count; ++k) {
      const double x = front * (-0.98 + 1.96 * k / (count - 1));
      std::vector<Vec3d> path;
      const auto out = lens.traceGhostFromScene({{x, 0.0, zLo}, {0.0, 0.0, 1.0}}, ghost->first, ghost->second,
                                                kWavelengthDNm, &path);
      if (!out || std::abs(out->direction.z) < 1e-9) continue;
      std::vector<Vec2d> pts{map(zLo, x)};
      for (const Vec3d& q : path) pts.push_back(map(q.z, q.x));
      // To the film, or to the drawing's edge on the way.
      double t = (filmZ - out->origin.z) / out->direction.z;
      const double xEnd = out->origin.x + out->direction.x * t;
      if (std::abs(xEnd) > xMax) t = (std::copysign(xMax, xEnd) - out->origin.x) / out->direction.x;
      const Vec3d end = out->origin + out->direction * t;
      pts.push_back(map(end.z, end.x));
      svg.polyline(pts, "class=\"ray\"");
    }
    svg.endGroup();
  }

  // Film plane, as tall as the sensor's diagonal.
  {
    const double h = view.halfDiagonalMm();
    svg.line(map(filmZ, h), map(filmZ, -h), "class=\"film\" id=\"film\"");
    svg.text(Vec2d{map(filmZ, h).x, map(filmZ, h).y - 8}, "film", "class=\"label\" text-anchor=\"middle\"");
  }

  // Cardinal points and pupils.
  svg.beginGroup("id=\"cardinal\"");
  const double tickH = 0.55 * aMax;
  struct Mark {
    double z;
    const char* label;
    bool plane;
  };
  std::vector<Mark> marks = {
      {p.frontPrincipalZ, "H", true}, {p.rearPrincipalZ, "H\u2032", true}, {p.rearFocalZ, "F\u2032", false}};
  int row = 0;
  for (const Mark& m : marks) {
    if (m.z < zLo || m.z > zHi) continue;
    if (m.plane) svg.line(map(m.z, tickH), map(m.z, -tickH), "class=\"plane\"");
    svg.circle(map(m.z, 0), 3.2, "class=\"point\"");
    const Vec2d at = map(m.z, 0);
    svg.text({at.x + 5, at.y + 16 + 14 * (row++ % 2)}, m.label, "class=\"label\" fill=\"#7d3c98\"");
  }
  for (const auto& [z, d, label] : {std::tuple{p.entrancePupilZ, p.entrancePupilDiameter, "EP"},
                                    std::tuple{p.exitPupilZ, p.exitPupilDiameter, "XP"}}) {
    if (z < zLo || z > zHi) continue;
    for (const double sgn : {1.0, -1.0}) {
      const Vec2d a = map(z, sgn * d / 2);
      svg.line({a.x, a.y - 5}, {a.x, a.y + 5}, "class=\"pupil\"");
    }
    svg.text(Vec2d{map(z, -d / 2).x, map(z, -d / 2).y + 20}, label,
             "class=\"label\" fill=\"#7d3c98\" text-anchor=\"middle\"");
  }
  svg.endGroup();

  // Legend, key and scale bar.
  double y = kPageH - 118;
  for (const FieldFan& fan : fans) {
    svg.line({50, y}, {90, y}, fmt::format("stroke=\"{}\" stroke-width=\"2\"", fan.colour));
    svg.text({98, y + 4}, fan.label, "class=\"label\"");
    y += 20;
  }
  if (ghost) {
    svg.line({50, y}, {90, y}, fmt::format("stroke=\"{}\" stroke-width=\"2\"", kGhostColour));
    svg.text({98, y + 4},
             fmt::format(
                 "ghost {},{}: an axial bundle reflected at surface {}, then at {} (numbered from the front)",
                 ghost->first + 1, ghost->second + 1, ghost->first + 1, ghost->second + 1),
             "class=\"label\"");
    y += 20;
  }
  svg.text({50, y + 6},
           "Fields: where the real chief ray (thick) lands: 0, \u00bd, 1 \u00d7 the sensor's half-diagonal. "
           "Dashed, "
           "ending in \u00d7: rays just outside the passing beam, up to where they are blocked.",
           "class=\"note\"");
  svg.text({50, y + 24},
           fmt::format(
               "H, H\u2032: principal planes at {:.2f}, {:.2f} mm; F\u2032: rear focal point at {:.2f} mm; "
               "EP, XP: entrance / exit pupil \u2300{:.2f} at {:.2f}, \u2300{:.2f} at {:.2f} mm (from the "
               "first vertex).",
               p.frontPrincipalZ, p.rearPrincipalZ, p.rearFocalZ, p.entrancePupilDiameter, p.entrancePupilZ,
               p.exitPupilDiameter, p.exitPupilZ),
           "class=\"note\"");
  const double barMm = niceLength((zHi - zLo) / 5);
  const Vec2d b0{kPageW - 60 - barMm * map.scale, kPageH - 112};
  svg.line(b0, {b0.x + barMm * map.scale, b0.y}, "class=\"scalebar\" id=\"scalebar\"");
  svg.line({b0.x, b0.y - 6}, {b0.x, b0.y + 6}, "class=\"scalebar\"");
  svg.line({b0.x + barMm * map.scale, b0.y - 6}, {b0.x + barMm * map.scale, b0.y + 6}, "class=\"scalebar\"");
  svg.text({b0.x + barMm * map.scale / 2, b0.y - 10}, fmt::format("{:g} mm", barMm),
           "class=\"label\" text-anchor=\"middle\"");
  return svg;
}

}  // namespace lensrt
