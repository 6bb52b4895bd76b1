#include "optics/spot_diagram.h"

#include <algorithm>
#include <cmath>

namespace lensrt {
namespace {

// Half-width in y of the passing beam at aim x: scan outward, then bisect.
double sagittalHalfWidth(const LensSystem& lens, const FieldPoint& field, double x, double maxY, double wl) {
  const auto ok = [&](double y) {
    return lens.traceFromScene(fieldRay(lens, field, {x, y}), wl).has_value();
  };
  if (!ok(0.0)) return 0.0;
  const int n = 400;
  double pass = 0.0, fail = maxY;
  for (int i = 1; i <= n; ++i) {
    const double y = maxY * i / n;
    if (!ok(y)) {
      fail = y;
      break;
    }
    pass = y;
  }
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (pass + fail);
    (ok(mid) ? pass : fail) = mid;
  }
  return pass;
}

}  // namespace

SpotDiagram spotDiagram(const LensSystem& lens, const FieldPoint& field, double filmDistanceMm, int grid,
                        double wavelengthNm) {
  SpotDiagram spot;
  spot.field = field;
  const auto band = meridionalPassBand(lens, field, wavelengthNm);
  if (!band) return spot;
  // The beam is symmetric in y; its widest sagittal extent need not be at
  // the band's centre (vignetting cuts a cat's eye), so sample a few x.
  const double maxY = 2.0 * lens.frontApertureRadius() + (band->hi - band->lo);
  double halfY = 0.0;
  for (int i = 0; i <= 8; ++i) {
    const double x = band->lo + (band->hi - band->lo) * (0.02 + 0.96 * i / 8.0);
    halfY = std::max(halfY, sagittalHalfWidth(lens, field, x, maxY, wavelengthNm));
  }
  halfY = std::max(halfY * 1.02, 1e-9);
  const double width = std::max(band->hi - band->lo, 2.0 * halfY);
  const double step = width / std::max(grid, 2);
  const double cx = 0.5 * (band->lo + band->hi);
  const int nx = std::max(1, static_cast<int>(std::ceil((band->hi - band->lo) / step)));
  const int ny = std::max(1, static_cast<int>(std::ceil(2.0 * halfY / step)));
  const double filmZ = lens.rearZ() + filmDistanceMm;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // Cell centres, symmetric about the band's centre and y = 0.
      const Vec2d aim{cx + (i + 0.5 - 0.5 * nx) * step, (j + 0.5 - 0.5 * ny) * step};
      ++spot.traced;
      const auto out = lens.traceFromScene(fieldRay(lens, field, aim), wavelengthNm);
      if (!out) continue;
      const double t = (filmZ - out->origin.z) / out->direction.z;
      spot.points.push_back({out->origin.x + out->direction.x * t, out->origin.y + out->direction.y * t});
    }
  if (spot.points.empty()) return spot;
  Vec2d sum;
  for (const Vec2d& p : spot.points) sum = sum + p;
  spot.centroid = sum / static_cast<double>(spot.points.size());
  double sum2 = 0.0;
  for (const Vec2d& p : spot.points) {
    const Vec2d d = p - spot.centroid;
    const double r2 = d.x * d.x + d.y * d.y;
    sum2 += r2;
    spot.maxRadiusMm = std::max(spot.maxRadiusMm, std::sqrt(r2));
  }
  spot.rmsRadiusMm = std::sqrt(sum2 / static_cast<double>(spot.points.size()));
  return spot;
}

}  // namespace lensrt
