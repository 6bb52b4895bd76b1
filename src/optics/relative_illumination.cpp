#include "optics/relative_illumination.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace lensrt {

FilmIrradiance filmIrradiance(const LensSystem& lens, double filmDistanceMm, double filmRadiusMm, int grid,
                              double wavelengthNm) {
  const double planeZ = lens.rearZ();
  const Vec3d film{filmRadiusMm, 0.0, planeZ + filmDistanceMm};
  // The fraction that gets through: 0 when blocked, else the Fresnel
  // transmittance when the lens models coatings (1 when it does not).
  const auto transmitted = [&](double x, double y) {
    const LensRay ray{film, Vec3d{x, y, planeZ} - film};
    const auto out = lens.traceFromFilm(ray, wavelengthNm);
    return out ? out->transmittance : 0.0;
  };
  const auto passes = [&](double x, double y) { return transmitted(x, y) > 0.0; };
  // Every passing ray leaves the rear surface inside its aperture; where its
  // line meets the vertex plane differs by the cap's depth times the slope.
  const Surface& rear = lens.prescription().surfaces.back();
  const double a = rear.apertureDiameter / 2.0;
  const double sag = rear.maxAbsSag();
  const double slope = (std::abs(filmRadiusMm) + a) / std::max(filmDistanceMm - sag, 0.1 * filmDistanceMm);
  const double half = 1.5 * a + sag * slope;

  // Coarse pass: the bounding box of what passes, dilated by one cell.
  const int coarse = 64;
  const double cstep = 2.0 * half / coarse;
  double xLo = kInfinity, xHi = -kInfinity, yHi = 0.0;
  for (int j = 0; j < coarse; ++j)
    for (int i = 0; i < coarse; ++i) {
      const double x = -half + (i + 0.5) * cstep, y = -half + (j + 0.5) * cstep;
      if (!passes(x, y)) continue;
      xLo = std::min(xLo, x);
      xHi = std::max(xHi, x);
      yHi = std::max(yHi, std::abs(y));
    }
  FilmIrradiance result;
  if (xLo > xHi) return result;
  xLo -= cstep;
  xHi += cstep;
  yHi += cstep;
  // Fine pass: midpoint rule on square cells, symmetric in y.
  const double step = std::max(xHi - xLo, 2.0 * yHi) / grid;
  const int nx = static_cast<int>(std::ceil((xHi - xLo) / step));
  const int ny = static_cast<int>(std::ceil(2.0 * yHi / step));
  const double cx = 0.5 * (xLo + xHi);
  const double d = filmDistanceMm;
  double omega = 0.0, area = 0.0, sx = 0.0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = cx + (i + 0.5 - 0.5 * nx) * step, y = (j + 0.5 - 0.5 * ny) * step;
      const double t = transmitted(x, y);
      if (!(t > 0.0)) continue;
      const double dx = x - film.x, r2 = dx * dx + y * y + d * d;
      const double cos2 = d * d / r2;
      omega += t * (cos2 * cos2 / (d * d));
      area += 1.0;
      sx += x;
    }
  const double cell = step * step;
  result.projectedSolidAngle = omega * cell;
  result.passingArea = area * cell;
  result.centroid = area > 0.0 ? Vec2d{sx / area, 0.0} : Vec2d{};
  return result;
}

std::vector<RelativeIlluminationPoint> relativeIlluminationCurve(const LensSystem& lens,
                                                                 double filmDistanceMm,
                                                                 double maxFilmRadiusMm, int points, int grid,
                                                                 double wavelengthNm) {
  const int n = std::max(points, 2);
  std::vector<RelativeIlluminationPoint> curve(n);
  const FilmIrradiance axis = filmIrradiance(lens, filmDistanceMm, 0.0, grid, wavelengthNm);
  for (int i = 0; i < n; ++i) {
    RelativeIlluminationPoint& p = curve[i];
    p.filmRadiusMm = maxFilmRadiusMm * i / (n - 1);
    if (!(axis.projectedSolidAngle > 0.0)) continue;
    const FilmIrradiance e =
        i == 0 ? axis : filmIrradiance(lens, filmDistanceMm, p.filmRadiusMm, grid, wavelengthNm);
    p.relative = e.projectedSolidAngle / axis.projectedSolidAngle;
    p.areaRatio = e.passingArea / axis.passingArea;
    if (e.passingArea > 0.0) {
      const double dx = e.centroid.x - p.filmRadiusMm;
      const double cos2 = filmDistanceMm * filmDistanceMm / (dx * dx + filmDistanceMm * filmDistanceMm);
      p.cos4 = cos2 * cos2;
    }
  }
  return curve;
}

}  // namespace lensrt
