#include "camera/lens_movements.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "camera/camera.h"
#include "core/constants.h"

namespace lensrt {

std::string LensMovements::describe() const {
  std::string s;
  char buf[96];
  if (shifted()) {
    std::snprintf(buf, sizeof buf, " shift=%.9g,%.9gmm", shiftMm.x, shiftMm.y);
    s += buf;
  }
  if (tilted()) {
    std::snprintf(buf, sizeof buf, " tilt=%.9gdeg", tiltDegrees);
    s += buf;
    if (tiltAxisDegrees != 0.0) {
      std::snprintf(buf, sizeof buf, " tilt-axis=%.9gdeg", tiltAxisDegrees);
      s += buf;
    }
  }
  return s;
}

std::optional<std::string> lensMovementsProblem(const LensMovements& m, const FilmGeometry& film) {
  char buf[160];
  if (!std::isfinite(m.shiftMm.x) || !std::isfinite(m.shiftMm.y)) return "the shift must be finite";
  if (!std::isfinite(m.tiltDegrees)) return "the tilt must be finite";
  if (!std::isfinite(m.tiltAxisDegrees)) return "the tilt axis must be finite";
  if (std::abs(m.shiftMm.x) > film.sensorWidthMm) {
    std::snprintf(buf, sizeof buf, "the shift's X (%g mm) must lie within +-%g mm (the sensor's width)",
                  m.shiftMm.x, film.sensorWidthMm);
    return buf;
  }
  if (std::abs(m.shiftMm.y) > film.sensorHeightMm) {
    std::snprintf(buf, sizeof buf, "the shift's Y (%g mm) must lie within +-%g mm (the sensor's height)",
                  m.shiftMm.y, film.sensorHeightMm);
    return buf;
  }
  if (std::abs(m.tiltDegrees) > kMaxTiltDegrees) {
    std::snprintf(buf, sizeof buf, "the tilt (%g degrees) must lie within +-%g degrees", m.tiltDegrees,
                  kMaxTiltDegrees);
    return buf;
  }
  if (std::abs(m.tiltAxisDegrees) > kMaxTiltAxisDegrees) {
    std::snprintf(buf, sizeof buf, "the tilt axis (%g degrees) must lie within +-%g degrees",
                  m.tiltAxisDegrees, kMaxTiltAxisDegrees);
    return buf;
  }
  return std::nullopt;
}

void checkLensMovements(const LensMovements& m, const FilmGeometry& film, const char* model) {
  if (const std::optional<std::string> problem = lensMovementsProblem(m, film))
    throw std::invalid_argument(std::string(model) + ": " + *problem);
}

MovedFilm::MovedFilm(const LensMovements& m) : shift_(m.shiftMm) {
  if (!m.tilted()) return;
  const double tilt = m.tiltDegrees * kPi / 180.0, axis = m.tiltAxisDegrees * kPi / 180.0;
  cosTilt_ = std::cos(tilt);
  sinTilt_ = std::sin(tilt);
  axis_ = {std::cos(axis), std::sin(axis)};
  across_ = {-axis_.y, axis_.x};
  // offset() maps `across` (upright) to (-across cos, -sin) and `axis` to
  // (-axis, 0): their cross product, toward the lens (-z), is this.
  normal_ = {sinTilt_ * across_.x, sinTilt_ * across_.y, -cosTilt_};
}

Vec3d MovedFilm::offset(Vec2d upright) const {
  const Vec2d w = upright + shift_;
  const double a = w.x * axis_.x + w.y * axis_.y, b = w.x * across_.x + w.y * across_.y;
  // Across the axis the film leaves its plane: b cos in it, -b sin along z
  // (a positive tilt takes the side below the axis, b < 0, away from the lens).
  const Vec2d lateral = axis_ * a + across_ * (b * cosTilt_);
  return {-lateral.x, -lateral.y, -b * sinTilt_};
}

std::optional<Vec2d> MovedFilm::uprightOfLine(const Vec2d& at, const Vec2d& slope) const {
  // The point (at + slope s, s) relative to the pivot, on the plane n.w = 0.
  const double along = normal_.x * slope.x + normal_.y * slope.y + normal_.z;
  if (!(std::abs(along) > 1e-12)) return std::nullopt;
  const double s = -(normal_.x * at.x + normal_.y * at.y) / along;
  return upright({at.x + slope.x * s, at.y + slope.y * s, s});
}

Vec2d MovedFilm::upright(const Vec3d& offset) const {
  const Vec2d lateral{-offset.x, -offset.y};
  const double a = lateral.x * axis_.x + lateral.y * axis_.y;
  const double b = (lateral.x * across_.x + lateral.y * across_.y) / cosTilt_;
  return axis_ * a + across_ * b - shift_;
}

namespace {
std::array<Vec2d, 4> corners(const FilmGeometry& f) {
  const double w = f.sensorWidthMm / 2, h = f.sensorHeightMm / 2;
  return {Vec2d{-w, -h}, Vec2d{w, -h}, Vec2d{w, h}, Vec2d{-w, h}};
}
}  // namespace

double MovedFilm::maxRadius(const FilmGeometry& film) const {
  // |offset.xy| <= |upright + shift| (the tilt only shortens), which is
  // convex: largest at a corner.
  double r = 0.0;
  for (const Vec2d& c : corners(film)) {
    const Vec2d w = c + shift_;
    r = std::max(r, std::hypot(w.x, w.y));
  }
  return r;
}

MovedFilm::DepthRange MovedFilm::depthRange(const FilmGeometry& film) const {
  DepthRange d{kInfinity, -kInfinity};
  for (const Vec2d& c : corners(film)) {
    const double z = offset(c).z;  // linear in the position: extremes at corners
    d.min = std::min(d.min, z);
    d.max = std::max(d.max, z);
  }
  return d;
}

}  // namespace lensrt
