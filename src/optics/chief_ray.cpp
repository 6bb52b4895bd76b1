#include "optics/chief_ray.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/constants.h"

namespace lensrt {
namespace {

constexpr double kTableStepRad = 0.5 * kPi / 180.0;
constexpr double kMaxFieldRad = 89.5 * kPi / 180.0;  // rays from infinity must travel toward +z
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The secant method on f(x), the chief ray's height at the stop against one
// parameter of the ray, from x0 with a first step `step`. f is nullopt where
// the ray misses a surface before the stop: the step is then halved back
// toward the last good x. Stops when the height is within kHeightTolerance
// of the stop's centre, a step within `tolerance`, or f no longer changes
// (converged to rounding); nullopt when it cannot. A picometre at the stop
// moves the image by about as much, 1e-7 of a 5 um pixel.
constexpr double kHeightToleranceMm = 1e-9;
struct Root {
  double x = 0.0;
  double slope = 0.0;  // df/dx from the last two evaluations (0 when there was one)
};
// A non-zero `derivative` (df/dx near the root, from a nearby solve) makes
// the first step Newton's.
template <class F>
std::optional<Root> secant(F&& f, double x0, double step, double tolerance, double derivative = 0.0) {
  const std::optional<double> f0 = f(x0);
  if (!f0) return std::nullopt;
  if (std::abs(*f0) <= kHeightToleranceMm) return Root{x0, derivative};
  if (derivative != 0.0 && std::isfinite(derivative)) step = -*f0 / derivative;
  double x1 = x0 + step;
  std::optional<double> f1 = f(x1);
  for (int k = 0; k < 40 && !f1; ++k) f1 = f(x1 = x0 + (step *= 0.5));
  if (!f1) return std::nullopt;
  double a = x0, fa = *f0, b = x1, fb = *f1;
  const auto root = [&] { return Root{b, (fb - fa) / (b - a)}; };
  for (int i = 0; i < 60; ++i) {
    if (std::abs(fb) <= kHeightToleranceMm || fb == fa) return root();
    double next = b - fb * (b - a) / (fb - fa);
    std::optional<double> fn = f(next);
    for (int k = 0; k < 40 && !fn; ++k) fn = f(next = 0.5 * (next + b));
    if (!fn || !std::isfinite(next)) return std::nullopt;
    a = b, fa = fb, b = next, fb = *fn;
    if (std::abs(b - a) <= tolerance || std::abs(fb) <= kHeightToleranceMm) return root();
  }
  return std::nullopt;
}

// The height along `u` at which a ray crosses the stop; nullopt when it
// never reaches it.
std::optional<double> stopHeight(const std::optional<Vec3d>& hit, const Vec2d& u) {
  if (!hit) return std::nullopt;
  return hit->x * u.x + hit->y * u.y;
}

double frontmostZ(const LensSystem& lens) {
  const Surface& s = lens.prescription().surfaces.front();
  // The opened front sphere reaches forward to its centre's plane when concave.
  return std::min({s.minSag(), s.isAspheric() ? 0.0 : std::min(0.0, s.radius)});
}

}  // namespace

ChiefRays::ChiefRays(const LensSystem& lens, double filmZ)
    : lens_(lens.prescription()),
      open_(lens_.withOpenRims()),
      filmZ_(filmZ),
      startZ_(frontmostZ(lens_) - 1.0) {
  // The axis's own entry, then fields outward, each search started from
  // the last field's chief ray (a continuation, robust where the pupil
  // moves far from its paraxial place, as in a fisheye).
  const double pupilZ = lens_.paraxial().entrancePupilZ;
  table_.push_back({0.0, 0.0, pupilZ, 0.0, 0.0});
  const int stop = lens_.paraxial().stopIndex;
  for (int k = 1; k * kTableStepRad <= kMaxFieldRad; ++k) {
    const double angle = k * kTableStepRad;
    const Vec3d d{-std::sin(angle), 0.0, std::cos(angle)};
    const auto ray = [&](double aim) {
      return LensRay{Vec3d{aim, 0.0, pupilZ} - d * ((pupilZ - startZ_) / d.z), d};
    };
    const auto height = [&](double aim) {
      const std::optional<LensSystem::PausedTrace> at = open_.traceFromSceneTo(ray(aim), stop);
      return stopHeight(at ? std::optional<Vec3d>(at->origin) : std::nullopt, {1.0, 0.0});
    };
    const std::optional<Root> root = secant(height, table_.back().aimHeight, 1e-6, 1e-12);
    if (!root) break;
    const double aim = root->x;
    const std::optional<LensRay> rear = open_.traceFromScene(ray(aim));
    if (!rear) break;
    const double filmX = rear->origin.x + rear->direction.x * (filmZ_ - rear->origin.z) / rear->direction.z;
    // The film side is searched by radius: keep the part where it grows.
    if (!(-filmX > table_.back().filmRadius)) break;
    table_.push_back(
        {angle, aim, pupilZ + aim / std::tan(angle), -filmX, rear->direction.x / rear->direction.z});
  }
}

double ChiefRays::tableFieldDeg() const {
  return table_.back().angle * 180.0 / kPi;
}

ChiefRays::Entry ChiefRays::atAngle(double angle) const {
  const double t = std::clamp(angle / kTableStepRad, 0.0, double(table_.size() - 1));
  const std::size_t i = std::min(std::size_t(t), table_.size() - 1);
  if (i + 1 >= table_.size()) return table_.back();
  const double w = t - double(i);
  const Entry& a = table_[i];
  const Entry& b = table_[i + 1];
  // The axis crossing at the axis is a limit: the first field's stands for it.
  const double axisA = i == 0 && table_.size() > 1 ? table_[1].axisZ : a.axisZ;
  return {angle, a.aimHeight + w * (b.aimHeight - a.aimHeight), axisA + w * (b.axisZ - axisA),
          a.filmRadius + w * (b.filmRadius - a.filmRadius), a.filmSlope + w * (b.filmSlope - a.filmSlope)};
}

ChiefRays::Entry ChiefRays::atFilmRadius(double radius) const {
  const auto above = std::upper_bound(table_.begin(), table_.end(), radius,
                                      [](double r, const Entry& e) { return r < e.filmRadius; });
  if (above == table_.begin()) return table_.front();
  if (above == table_.end()) return table_.back();
  const Entry& a = *(above - 1);
  const Entry& b = *above;
  const double w = (radius - a.filmRadius) / (b.filmRadius - a.filmRadius);
  return {a.angle + w * (b.angle - a.angle), a.aimHeight + w * (b.aimHeight - a.aimHeight),
          a.axisZ + w * (b.axisZ - a.axisZ), radius, a.filmSlope + w * (b.filmSlope - a.filmSlope)};
}

ChiefRayImage ChiefRays::image(const LensRay& sceneRay, double wavelengthNm) const {
  // The open lens does the real lens's arithmetic but for the rims: where
  // the real lens passes the ray, its bits are the same.
  std::optional<LensRay> rear = lens_.traceFromScene(sceneRay, wavelengthNm);
  const ChiefRayStatus status = rear ? ChiefRayStatus::Passes : ChiefRayStatus::Blocked;
  if (!rear) rear = open_.traceFromScene(sceneRay, wavelengthNm);
  return imageOf(rear, status);
}

ChiefRayImage ChiefRays::imageOf(const std::optional<LensRay>& rear, ChiefRayStatus status) const {
  if (!rear) return {ChiefRayStatus::Blocked, {kNaN, kNaN}};
  const double t = (filmZ_ - rear->origin.z) / rear->direction.z;
  return {status,
          {rear->origin.x + rear->direction.x * t, rear->origin.y + rear->direction.y * t},
          rear->direction};
}

ChiefRayImage ChiefRays::imageFrom(const LensSystem::PausedTrace& paused, std::span<const Vec3d> hits,
                                   double wavelengthNm) const {
  // The same traces as image()'s, resumed where the search left them.
  std::optional<LensRay> rear =
      lens_.rimsHold(hits) ? lens_.resumeFromScene(paused, wavelengthNm) : std::nullopt;
  const ChiefRayStatus status = rear ? ChiefRayStatus::Passes : ChiefRayStatus::Blocked;
  if (!rear) rear = open_.resumeFromScene(paused, wavelengthNm);
  return imageOf(rear, status);
}

ChiefRayImage ChiefRays::ofPoint(const Vec3d& p, double wavelengthNm) const {
  return ofPoint(p, wavelengthNm, nullptr);
}

ChiefRayImage ChiefRays::ofPoint(const Vec3d& p, double wavelengthNm, ChiefRayHint* hint) const {
  if (!(p.z < startZ_ + 1.0) || !isFinite(p)) return {ChiefRayStatus::Behind, {kNaN, kNaN}};
  const double r = std::hypot(p.x, p.y);
  if (r == 0.0) return image({p, {0.0, 0.0, 1.0}}, wavelengthNm);
  const Vec2d u{p.x / r, p.y / r};
  // The chief ray crosses the axis at its field's entrance pupil: a nearby
  // point's solve says where; else find the field whose crossing the line
  // from the point meets (a fixed point, which the table's slow variation
  // makes converge at once).
  const bool hinted = hint && hint->valid() && double(hint->axisZ) > p.z;
  const double offset = hinted ? double(hint->axisOffset) : 0.0;
  double axisZ = hinted ? double(hint->axisZ) : lens_.paraxial().entrancePupilZ;
  for (int i = 0; i < (hinted ? 1 : 3); ++i) {
    const double z = atAngle(std::atan2(r, axisZ - p.z)).axisZ + offset;
    if (!(z > p.z)) break;
    axisZ = z;
  }
  const int stop = lens_.paraxial().stopIndex;
  const auto ray = [&](double slope) { return LensRay{p, {slope * u.x, slope * u.y, 1.0}}; };
  // Each evaluation traces to the stop; the last one's trace goes on to the
  // film from there (its hits before the stop tell whether the real rims
  // hold it).
  std::vector<Vec3d> hits;
  hits.reserve(std::size_t(stop) + 1);
  std::optional<LensSystem::PausedTrace> paused;
  double pausedSlope = kNaN;
  const auto height = [&](double slope) -> std::optional<double> {
    hits.clear();
    paused = open_.traceFromSceneTo(ray(slope), stop, wavelengthNm, &hits);
    pausedSlope = slope;
    if (!paused) return std::nullopt;
    return paused->origin.x * u.x + paused->origin.y * u.y;
  };
  const double distance = std::max(axisZ - p.z, 1e-9);
  const double slope0 = -r / distance;
  const std::optional<Root> slope = secant(height, slope0, 1e-7 * (1.0 + std::abs(slope0)), 1e-15,
                                           hinted ? double(hint->heightPerSlope) * distance : 0.0);
  if (!slope) return {ChiefRayStatus::Blocked, {kNaN, kNaN}};
  if (hint && slope->x < 0.0 && slope->slope != 0.0) {
    // The solved ray's own axis crossing, and its height's rate per mm.
    const double crossing = p.z - r / slope->x;
    if (crossing > p.z)
      *hint = {float(crossing), float(crossing - atAngle(std::atan2(r, crossing - p.z)).axisZ),
               float(slope->slope / (crossing - p.z))};
  }
  if (paused && pausedSlope == slope->x) return imageFrom(*paused, hits, wavelengthNm);
  return image(ray(slope->x), wavelengthNm);
}

ChiefRayImage ChiefRays::ofDirection(const Vec3d& direction, double wavelengthNm) const {
  if (!(direction.z > 0.0) || !isFinite(direction)) return {ChiefRayStatus::Behind, {kNaN, kNaN}};
  const Vec3d d = normalize(direction);
  const double sine = std::hypot(d.x, d.y);
  if (sine == 0.0) return image({{0.0, 0.0, startZ_}, d}, wavelengthNm);
  const Vec2d u{-d.x / sine, -d.y / sine};  // toward the object
  const double pupilZ = lens_.paraxial().entrancePupilZ;
  const int stop = lens_.paraxial().stopIndex;
  const auto ray = [&](double aim) {
    return LensRay{Vec3d{aim * u.x, aim * u.y, pupilZ} - d * ((pupilZ - startZ_) / d.z), d};
  };
  const auto height = [&](double aim) {
    const std::optional<LensSystem::PausedTrace> at = open_.traceFromSceneTo(ray(aim), stop, wavelengthNm);
    return stopHeight(at ? std::optional<Vec3d>(at->origin) : std::nullopt, u);
  };
  const std::optional<Root> aim = secant(height, atAngle(std::atan2(sine, d.z)).aimHeight, 1e-6, 1e-12);
  if (!aim) return {ChiefRayStatus::Blocked, {kNaN, kNaN}};
  return image(ray(aim->x), wavelengthNm);
}

ChiefRayToScene ChiefRays::ofFilmPoint(const Vec2d& film, double wavelengthNm) const {
  return ofFilmPoint(Vec3d{film.x, film.y, filmZ_}, wavelengthNm);
}

ChiefRayToScene ChiefRays::ofFilmPoint(const Vec3d& origin, double wavelengthNm) const {
  const LensRay blocked{{kNaN, kNaN, kNaN}, {kNaN, kNaN, kNaN}};
  if (!isFinite(origin)) return {ChiefRayStatus::Blocked, blocked};
  const Vec2d film{origin.x, origin.y};
  const double r = std::hypot(film.x, film.y);
  const auto toScene = [&](const LensRay& ray) -> ChiefRayToScene {
    if (std::optional<LensRay> out = lens_.traceFromFilm(ray, wavelengthNm))
      return {ChiefRayStatus::Passes, *out};
    if (std::optional<LensRay> out = open_.traceFromFilm(ray, wavelengthNm))
      return {ChiefRayStatus::Blocked, *out};
    return {ChiefRayStatus::Blocked, blocked};
  };
  if (r == 0.0) return toScene({origin, {0.0, 0.0, -1.0}});
  const Vec2d u{film.x / r, film.y / r};
  const int stop = lens_.paraxial().stopIndex;
  // The table's image-side slopes are radial toward -x, the film point's
  // direction there: the same radial slope here.
  const auto ray = [&](double slope) { return LensRay{origin, {slope * u.x, slope * u.y, -1.0}}; };
  const auto height = [&](double slope) {
    return stopHeight(open_.hitFromFilm(ray(slope), stop, wavelengthNm), u);
  };
  const double slope0 = atFilmRadius(r).filmSlope;
  const std::optional<Root> slope = secant(height, slope0, 1e-7 * (1.0 + std::abs(slope0)), 1e-15);
  if (!slope) return {ChiefRayStatus::Blocked, blocked};
  return toScene(ray(slope->x));
}

}  // namespace lensrt
