#include "optics/lens_system.h"

#include <cmath>

namespace lensrt {

bool refract(const Vec3d& d, const Vec3d& n, double n1, double n2, Vec3d& out) {
  const double eta = n1 / n2;
  const double cosI = -dot(n, d);
  const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
  if (sin2T >= 1.0) return false;  // total internal reflection
  const double cosT = std::sqrt(1.0 - sin2T);
  // Unit in, unit out: no renormalisation needed (callers normalise once at the end).
  out = d * eta + n * (eta * cosI - cosT);
  return true;
}

LensSystem::LensSystem(LensPrescription prescription) : prescription_(std::move(prescription)) {
  validatePrescription(prescription_);
  paraxial_ = computeParaxial(prescription_);
  double z = 0.0;
  for (const Surface& s : prescription_.surfaces) {
    TraceSurface t;
    t.z = z;
    t.radius = s.radius;
    t.invRadius = s.radius != 0.0 ? 1.0 / s.radius : 0.0;
    t.apertureRadius = s.apertureDiameter / 2.0;
    t.apertureRadius2 = t.apertureRadius * t.apertureRadius;
    t.isStop = s.isStop;
    t.ndAfter = s.medium.nd;
    t.after = Dispersion::of(s.medium);
    surfaces_.push_back(t);
    z += s.thickness;
  }
}

double LensSystem::indexAfter(int i, double wavelengthNm) const {
  if (i < 0) return 1.0;  // the scene is air
  const TraceSurface& s = surfaces_[i];
  return wavelengthNm == kWavelengthDNm ? s.ndAfter : s.after.index(wavelengthNm);
}

bool LensSystem::intersect(const TraceSurface& s, const Vec3d& o, const Vec3d& d, Vec3d& hit, Vec3d& normal) {
  // Work relative to the vertex: a sphere through the vertex is
  // x^2 + y^2 + z^2 - 2 R z = 0, which avoids cancellation for large R.
  const Vec3d p{o.x, o.y, o.z - s.z};
  double t;
  if (s.radius == 0.0) {
    if (d.z == 0.0) return false;
    t = -p.z / d.z;
    if (!(t >= -1e-9)) return false;
    hit = p + d * t;
    normal = {0.0, 0.0, d.z > 0.0 ? -1.0 : 1.0};
  } else {
    const double R = s.radius;
    const double b = dot(p, d) - R * d.z;
    const double c = dot(p, p) - 2.0 * R * p.z;
    const double disc = b * b - c;
    if (!(disc >= 0.0)) return false;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    double t0 = q, t1 = q != 0.0 ? c / q : 0.0;
    if (t0 > t1) std::swap(t0, t1);
    // The first crossing of the cap around the vertex (not the far hemisphere).
    const auto onCap = [&](double tt) { return tt >= -1e-9 && (p.z + d.z * tt - R) * R < 0.0; };
    if (onCap(t0))
      t = t0;
    else if (onCap(t1))
      t = t1;
    else
      return false;
    hit = p + d * t;
    normal = Vec3d{hit.x, hit.y, hit.z - R} * s.invRadius;
    if (dot(normal, d) > 0.0) normal = -normal;
  }
  if (hit.x * hit.x + hit.y * hit.y > s.apertureRadius2) return false;
  hit.z += s.z;
  return true;
}

std::optional<LensRay> LensSystem::traceFromFilm(const LensRay& ray, double wavelengthNm,
                                                 std::vector<Vec3d>* path) const {
  if (!isFinite(ray.origin) || !isFinite(ray.direction) || !(ray.direction.z < 0.0)) return std::nullopt;
  Vec3d o = ray.origin;
  Vec3d d = normalize(ray.direction);
  for (int i = surfaceCount() - 1; i >= 0; --i) {
    const TraceSurface& s = surfaces_[i];
    Vec3d hit, normal;
    if (!intersect(s, o, d, hit, normal)) return std::nullopt;
    if (path) path->push_back(hit);
    o = hit;
    if (s.isStop) continue;
    const double n1 = indexAfter(i, wavelengthNm);
    const double n2 = indexAfter(i - 1, wavelengthNm);
    if (n1 != n2 && !refract(d, normal, n1, n2, d)) return std::nullopt;
    if (!(d.z < 0.0)) return std::nullopt;  // turned back toward the film
  }
  if (!isFinite(o) || !isFinite(d)) return std::nullopt;
  return LensRay{o, normalize(d)};
}

std::optional<LensRay> LensSystem::traceFromScene(const LensRay& ray, double wavelengthNm,
                                                  std::vector<Vec3d>* path) const {
  if (!isFinite(ray.origin) || !isFinite(ray.direction) || !(ray.direction.z > 0.0)) return std::nullopt;
  Vec3d o = ray.origin;
  Vec3d d = normalize(ray.direction);
  for (int i = 0; i < surfaceCount(); ++i) {
    const TraceSurface& s = surfaces_[i];
    Vec3d hit, normal;
    if (!intersect(s, o, d, hit, normal)) return std::nullopt;
    if (path) path->push_back(hit);
    o = hit;
    if (s.isStop) continue;
    const double n1 = indexAfter(i - 1, wavelengthNm);
    const double n2 = indexAfter(i, wavelengthNm);
    if (n1 != n2 && !refract(d, normal, n1, n2, d)) return std::nullopt;
    if (!(d.z > 0.0)) return std::nullopt;
  }
  if (!isFinite(o) || !isFinite(d)) return std::nullopt;
  return LensRay{o, normalize(d)};
}

}  // namespace lensrt
