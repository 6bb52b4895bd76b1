#include "optics/pupil_function.h"

#include <algorithm>
#include <cmath>

namespace lensrt {
namespace {

// A traced ray of the field: where it leaves the lens, its optical path from
// the object's wavefront to there, and its intensity transmittance.
struct Traced {
  Vec3d exit;
  Vec3d direction;
  double opticalPathMm = 0.0;
  double transmittance = 0.0;
};

class FieldTracer {
 public:
  FieldTracer(const LensSystem& lens, const FieldPoint& field, double wavelengthNm,
              const StopTransmittance& stop)
      : lens_(lens), field_(field), wavelengthNm_(wavelengthNm), stop_(stop) {
    for (const Surface& s : lens.prescription().surfaces) index_.push_back(indexOf(s.medium));
  }

  // nullopt when the lens blocks the ray; a stop shape that blocks it gives
  // transmittance 0 (the ray's geometry still serves the edge cells).
  std::optional<Traced> trace(Vec2d aim) {
    const LensRay in = fieldRay(lens_, field_, aim);
    path_.clear();
    const std::optional<LensRay> out = lens_.traceFromScene(in, wavelengthNm_, &path_);
    if (!out || path_.size() != index_.size()) return std::nullopt;
    // From the object's wavefront to the first surface (object space is air):
    // a plane through the origin for an object at infinity, else a sphere
    // about the object point.
    const Vec3d d = normalize(in.direction);
    double opl = std::isinf(field_.objectDistanceMm) ? dot(d, path_[0]) : length(path_[0] - in.origin);
    for (std::size_t s = 0; s + 1 < path_.size(); ++s) opl += index_[s] * length(path_[s + 1] - path_[s]);
    double t = out->transmittance;
    if (stop_) {
      const Vec3d& hit = path_[std::size_t(lens_.paraxial().stopIndex)];
      t *= std::clamp(stop_(hit.x, hit.y), 0.0, 1.0);
    }
    return Traced{out->origin, normalize(out->direction), opl, t};
  }

  // The object's light per unit aim-plane area around `aim`, relative: 1 for
  // an object at infinity (a collimated beam), cos(alpha) / r^2 for a point.
  double density(Vec2d aim) const {
    if (std::isinf(field_.objectDistanceMm)) return 1.0;
    const LensRay in = fieldRay(lens_, field_, aim);
    const Vec3d v = Vec3d{aim.x, aim.y, 0.0} - in.origin;
    const double r2 = dot(v, v);
    return std::abs(v.z) / (std::sqrt(r2) * r2);
  }

 private:
  double indexOf(const Medium& m) const {
    return wavelengthNm_ == kWavelengthDNm ? m.nd : Dispersion::of(m).index(wavelengthNm_);
  }
  const LensSystem& lens_;
  FieldPoint field_;
  double wavelengthNm_;
  StopTransmittance stop_;
  std::vector<double> index_;  // after each surface
  std::vector<Vec3d> path_;
};

Vec2d lateral(const Vec3d& v) {
  return {v.x, v.y};
}

// aim + J (target - direction), J = d(aim) / d(L, M).
Vec2d aimToward(Vec2d aim, const double (&j)[2][2], Vec2d error) {
  return {aim.x + j[0][0] * error.x + j[0][1] * error.y, aim.y + j[1][0] * error.x + j[1][1] * error.y};
}

}  // namespace

std::optional<PupilBeam> pupilBeam(const LensSystem& lens, const FieldPoint& field, double wavelengthNm) {
  const std::optional<double> chiefAim = chiefRayAim(lens, field, wavelengthNm);
  if (!chiefAim) return std::nullopt;
  FieldTracer tracer(lens, field, wavelengthNm, {});
  const auto chief = tracer.trace({*chiefAim, 0.0});
  if (!chief) return std::nullopt;
  PupilBeam beam;
  beam.chiefAim = *chiefAim;
  beam.chiefExit = chief->exit;
  beam.chiefDirection = chief->direction;
  const Vec2d d0 = lateral(chief->direction);
  // The Jacobian d(L, M) / d(aim) by central differences, a small fraction
  // of the entrance pupil, then inverted.
  const double h = 1e-4 * std::max(lens.paraxial().entrancePupilDiameter, 1e-3);
  double dDir[2][2];
  for (int k = 0; k < 2; ++k) {
    const Vec2d step = k == 0 ? Vec2d{h, 0.0} : Vec2d{0.0, h};
    const auto plus = tracer.trace(Vec2d{*chiefAim, 0.0} + step);
    const auto minus = tracer.trace(Vec2d{*chiefAim, 0.0} - step);
    if (!plus || !minus) return std::nullopt;
    const Vec2d g = (lateral(plus->direction) - lateral(minus->direction)) / (2.0 * h);
    dDir[0][k] = g.x;
    dDir[1][k] = g.y;
  }
  const double det = dDir[0][0] * dDir[1][1] - dDir[0][1] * dDir[1][0];
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return std::nullopt;
  beam.aimPerDirection[0][0] = dDir[1][1] / det;
  beam.aimPerDirection[0][1] = -dDir[0][1] / det;
  beam.aimPerDirection[1][0] = -dDir[1][0] / det;
  beam.aimPerDirection[1][1] = dDir[0][0] / det;
  // The beam's extent: a scan of the aim plane around the chief ray, widened
  // while rays still pass at the scan's border.
  const auto band = meridionalPassBand(lens, field, wavelengthNm);
  double w = 0.6 * std::max(band ? band->hi - band->lo : 0.0, lens.paraxial().entrancePupilDiameter);
  const int n = 48;
  for (int attempt = 0; attempt < 6; ++attempt, w *= 1.5) {
    const double step = 2.0 * w / n;
    double reach = 0.0;
    bool atBorder = false;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const Vec2d aim{*chiefAim - w + i * step, -w + j * step};
        const auto ray = tracer.trace(aim);
        if (!ray) continue;
        const Vec2d d = lateral(ray->direction) - d0;
        reach = std::max({reach, std::abs(d.x), std::abs(d.y)});
        atBorder = atBorder || i == 0 || j == 0 || i == n || j == n;
      }
    if (atBorder) continue;
    // A scan step's worth of directions on either side, so no passing ray
    // falls between the last scanned one and the grid's edge.
    const double dirStep =
        step * std::max(std::hypot(dDir[0][0], dDir[1][0]), std::hypot(dDir[0][1], dDir[1][1]));
    beam.halfWidth = reach + 2.0 * dirStep;
    return beam;
  }
  return std::nullopt;
}

ReferenceSphere referenceSphere(const LensSystem& lens, const PupilBeam& beam, double filmZ) {
  const Vec3d& q = beam.chiefExit;
  const Vec3d& d = beam.chiefDirection;
  const Vec3d image = q + d * ((filmZ - q.z) / d.z);
  const Vec3d pupil = q + d * ((lens.paraxial().exitPupilZ - q.z) / d.z);
  return {image, length(image - pupil)};
}

PupilRays::PupilRays(const LensSystem& lens, const FieldPoint& field, double wavelengthNm,
                     const PupilBeam& beam, const PupilGrid& grid, const StopTransmittance& stop)
    : grid_(grid), wavelengthNm_(wavelengthNm) {
  FieldTracer tracer(lens, field, wavelengthNm, stop);
  const int n = grid.size();
  const auto& jac = beam.aimPerDirection;
  const auto at = [n](int i, int j) { return std::size_t(j) * std::size_t(n) + std::size_t(i); };
  // Each grid point's ray, aimed by Newton steps with the chief ray's
  // Jacobian from its neighbour's aim (the map from aim to direction is
  // smooth, so 2-4 steps reach 1e-13).
  struct Aimed {
    bool traced = false;
    Vec2d aim;
    Traced ray;
  };
  std::vector<Aimed> aimed(std::size_t(n) * std::size_t(n));
  const Vec2d chiefAim{beam.chiefAim, 0.0};
  const Vec2d chiefDir = lateral(beam.chiefDirection);
  const double tolerance = 1e-12 * std::max(grid.spacing * grid.half, 1e-6);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2d target = grid.direction(i, j);
      if (std::max(std::abs(target.x - chiefDir.x), std::abs(target.y - chiefDir.y)) > beam.halfWidth)
        continue;
      Vec2d aim = aimToward(chiefAim, jac, target - chiefDir);
      for (const auto& [di, dj] : {std::pair{-1, 0}, std::pair{0, -1}})
        if (i + di >= 0 && j + dj >= 0 && aimed[at(i + di, j + dj)].traced) {
          const Aimed& nb = aimed[at(i + di, j + dj)];
          aim = aimToward(nb.aim, jac, target - lateral(nb.ray.direction));
          break;
        }
      for (int iteration = 0; iteration < 12; ++iteration) {
        const auto ray = tracer.trace(aim);
        if (!ray) break;
        const Vec2d error = target - lateral(ray->direction);
        if (std::max(std::abs(error.x), std::abs(error.y)) < tolerance || iteration == 11) {
          aimed[at(i, j)] = {true, aim, *ray};
          break;
        }
        aim = aimToward(aim, jac, error);
      }
    }
  // Light per cell: the aim-plane area a cell of directions takes (the
  // Jacobian of the aims over the grid, by differences), times the object's
  // light per aim area, relative to the chief ray's.
  const double cellArea0 =
      std::abs(jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0]) * grid.spacing * grid.spacing;
  const double density0 = tracer.density(chiefAim) * cellArea0;
  const auto aimDerivative = [&](int i, int j, int di, int dj) {
    const bool plus = i + di < n && j + dj < n && aimed[at(i + di, j + dj)].traced;
    const bool minus = i - di >= 0 && j - dj >= 0 && aimed[at(i - di, j - dj)].traced;
    const Vec2d here = aimed[at(i, j)].aim;
    if (plus && minus) return (aimed[at(i + di, j + dj)].aim - aimed[at(i - di, j - dj)].aim) / 2.0;
    if (plus) return aimed[at(i + di, j + dj)].aim - here;
    if (minus) return here - aimed[at(i - di, j - dj)].aim;
    const Vec2d g{jac[0][di ? 0 : 1], jac[1][di ? 0 : 1]};
    return g * grid.spacing;
  };
  const auto relativeLight = [&](int i, int j) {
    const Vec2d a = aimDerivative(i, j, 1, 0), b = aimDerivative(i, j, 0, 1);
    return std::abs(a.x * b.y - a.y * b.x) * tracer.density(aimed[at(i, j)].aim) / density0;
  };
  samples_.assign(aimed.size(), Sample{});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Aimed& a = aimed[at(i, j)];
      if (!a.traced) continue;
      const double light = a.ray.transmittance * relativeLight(i, j);
      samples_[at(i, j)] = {a.ray.exit, a.ray.direction, a.ray.opticalPathMm, std::sqrt(light), light};
    }
  // Edge cells (passing next to blocked, either way): the mean amplitude of
  // 6 x 6 sub-rays aimed from the nearest traced ray; a cell whose centre is
  // blocked takes its geometry from its sub-ray nearest the centre.
  constexpr int kSub = 6;
  std::vector<Sample> edged = samples_;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const bool lit = samples_[at(i, j)].amplitude > 0.0;
      bool edge = false;
      const Aimed* ref = aimed[at(i, j)].traced ? &aimed[at(i, j)] : nullptr;
      int refI = i, refJ = j;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= n || jj >= n) continue;
          edge = edge || (samples_[at(ii, jj)].amplitude > 0.0) != lit;
          if (!ref && aimed[at(ii, jj)].traced) ref = &aimed[at(ii, jj)], refI = ii, refJ = jj;
        }
      if (!edge || !ref) continue;
      const Vec2d centre = grid.direction(i, j);
      double sum = 0.0, sumLight = 0.0, nearest = kInfinity;
      std::optional<Traced> nearestRay;
      for (int b = 0; b < kSub; ++b)
        for (int a = 0; a < kSub; ++a) {
          const Vec2d offset{((a + 0.5) / kSub - 0.5) * grid.spacing,
                             ((b + 0.5) / kSub - 0.5) * grid.spacing};
          const Vec2d target = centre + offset;
          const auto ray = tracer.trace(aimToward(ref->aim, jac, target - lateral(ref->ray.direction)));
          if (!ray || !(ray->transmittance > 0.0)) continue;
          sum += std::sqrt(ray->transmittance);
          sumLight += ray->transmittance;
          const double r = offset.x * offset.x + offset.y * offset.y;
          if (r < nearest) nearest = r, nearestRay = ray;
        }
      if (!nearestRay) {
        edged[at(i, j)].amplitude = edged[at(i, j)].light = 0.0;
        continue;
      }
      Sample& s = edged[at(i, j)];
      if (!aimed[at(i, j)].traced)
        s = {nearestRay->exit, nearestRay->direction, nearestRay->opticalPathMm, 0.0, 0.0};
      const double cellLight = relativeLight(refI, refJ);
      s.amplitude = sum / (kSub * kSub) * std::sqrt(cellLight);
      s.light = sumLight / (kSub * kSub) * cellLight;
    }
  samples_ = std::move(edged);
  const auto chief = tracer.trace(chiefAim);
  if (chief) chief_ = {chief->exit, chief->direction, chief->opticalPathMm, 1.0, 1.0};
}

namespace {

// The optical path from a ray's exit point to the reference sphere (air):
// the crossing on the pupil's side of the centre (the smaller root; negative
// when the sphere lies behind the exit point).
double toSphere(const Vec3d& exit, const Vec3d& d, const ReferenceSphere& s) {
  const Vec3d v = exit - s.centre;
  const double b = dot(v, d);
  const double c = dot(v, v) - s.radiusMm * s.radiusMm;
  const double disc = std::max(0.0, b * b - c);
  return -b - std::sqrt(disc);
}

}  // namespace

PupilFunction PupilRays::at(const ReferenceSphere& reference) const {
  PupilFunction p;
  p.grid = grid_;
  p.wavelengthNm = wavelengthNm_;
  p.reference = reference;
  const std::size_t count = samples_.size();
  p.amplitude.assign(count, 0.0);
  p.opdWaves.assign(count, 0.0);
  const double waveMm = wavelengthNm_ * 1e-6;
  const double chiefPath = chief_.opticalPathMm + toSphere(chief_.exit, chief_.direction, reference);
  double sumW = 0.0, sumW2 = 0.0, sumI = 0.0;
  double lo = kInfinity, hi = -kInfinity;
  for (std::size_t k = 0; k < count; ++k) {
    const Sample& s = samples_[k];
    if (!(s.amplitude > 0.0)) continue;
    const double path = s.opticalPathMm + toSphere(s.exit, s.direction, reference);
    const double w = (path - chiefPath) / waveMm;
    p.amplitude[k] = s.amplitude;
    p.opdWaves[k] = w;
    p.light += s.light;
    const double intensity = s.light;
    sumI += intensity;
    sumW += intensity * w;
    sumW2 += intensity * w * w;
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  if (sumI > 0.0) {
    const double mean = sumW / sumI;
    p.rmsWaves = std::sqrt(std::max(0.0, sumW2 / sumI - mean * mean));
    p.peakToValleyWaves = hi - lo;
  }
  const int n = grid_.size();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(n) + std::size_t(i);
      if (!(p.amplitude[k] > 0.0)) continue;
      if (i + 1 < n && p.amplitude[k + 1] > 0.0)
        p.maxStepWaves = std::max(p.maxStepWaves, std::abs(p.opdWaves[k + 1] - p.opdWaves[k]));
      if (j + 1 < n && p.amplitude[k + std::size_t(n)] > 0.0)
        p.maxStepWaves = std::max(p.maxStepWaves, std::abs(p.opdWaves[k + std::size_t(n)] - p.opdWaves[k]));
    }
  return p;
}

}  // namespace lensrt
