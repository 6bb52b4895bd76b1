#include "optics/asphere.h"

#include <algorithm>
#include <cmath>

namespace lensrt {

namespace {

constexpr double kBehind = -1e-9;  // hits this far behind the origin still count (as for spheres)

// The smallest root t >= kBehind of the base conic c (x^2 + y^2 + (1 + k) z^2)
// - 2 z = 0 on the sheet through the vertex ((1 + k) c z <= 1); nullopt when
// none.
std::optional<double> conicHit(const AsphereProfile& a, const Vec3d& p, const Vec3d& d) {
  const double c = a.curvature, q = 1.0 + a.conic;
  const double qa = c * (d.x * d.x + d.y * d.y + q * d.z * d.z);
  const double qb = c * (p.x * d.x + p.y * d.y + q * p.z * d.z) - d.z;  // half the linear term
  const double qc = c * (p.x * p.x + p.y * p.y + q * p.z * p.z) - 2.0 * p.z;
  double roots[2];
  int count = 0;
  if (std::abs(qa) < 1e-300) {
    if (qb == 0.0) return std::nullopt;
    roots[count++] = -qc / (2.0 * qb);
  } else {
    const double disc = qb * qb - qa * qc;
    if (!(disc >= 0.0)) return std::nullopt;
    // The cancellation-free pair of roots.
    const double s = -(qb + std::copysign(std::sqrt(disc), qb));
    roots[count++] = s / qa;
    if (s != 0.0) roots[count++] = qc / s;
  }
  std::optional<double> best;
  for (int i = 0; i < count; ++i) {
    const double t = roots[i];
    if (!(t >= kBehind) || (best && t >= *best)) continue;
    if (q * c * (p.z + d.z * t) > 1.0) continue;  // the far sheet or the far side of an ellipsoid
    best = t;
  }
  return best;
}

}  // namespace

std::optional<double> intersectAsphere(const AsphereProfile& profile, double rMax, const Vec3d& p,
                                       const Vec3d& d) {
  const double rMax2 = rMax * rMax;
  // f(t) = z(t) - sag(r(t)): negative in front of the surface (scene side).
  const auto f = [&](double t) {
    const double x = p.x + d.x * t, y = p.y + d.y * t;
    const double r2 = std::min(x * x + y * y, rMax2);
    return p.z + d.z * t - profile.sag(r2).value_or(0.0);
  };
  // The span of t inside the cylinder r <= rMax (and not behind the origin).
  const double A = d.x * d.x + d.y * d.y, B = p.x * d.x + p.y * d.y, C = p.x * p.x + p.y * p.y - rMax2;
  double lo = kBehind, hi = 0.0;
  if (A == 0.0) {
    // Parallel to the axis: r is constant, the sag is one number.
    if (C > 0.0 || d.z == 0.0) return std::nullopt;
    const double t = -f(0.0) / d.z;
    return t >= kBehind && std::isfinite(t) ? std::optional(t) : std::nullopt;
  }
  const double disc = B * B - A * C;
  if (!(disc >= 0.0)) return std::nullopt;  // passes beside the cylinder
  const double root = std::sqrt(disc);
  lo = std::max(lo, (-B - root) / A);
  hi = (-B + root) / A;
  if (!(lo <= hi)) return std::nullopt;

  // Newton from the base conic's hit (the plane's for a flat base).
  double t = 0.0;
  if (const auto tc = conicHit(profile, p, d); tc && *tc >= lo && *tc <= hi)
    t = *tc;
  else if (d.z != 0.0 && -p.z / d.z >= lo && -p.z / d.z <= hi)
    t = -p.z / d.z;
  else
    t = 0.5 * (lo + hi);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double x = p.x + d.x * t, y = p.y + d.y * t;
    const double r2 = x * x + y * y;
    const auto z = profile.sag(r2);
    const auto g = profile.slopeOverR(r2);
    if (!z || !g) break;
    const double value = p.z + d.z * t - *z;
    const double slope = d.z - *g * (x * d.x + y * d.y);
    if (slope == 0.0 || !std::isfinite(slope)) break;
    const double step = value / slope;
    t -= step;
    if (!(t >= lo && t <= hi)) break;
    if (std::abs(step) <= 1e-12 * std::max(1.0, std::abs(t))) return t;
  }

  // Fallback: the first sign change of f across the span, then bisection.
  constexpr int kSamples = 64;
  double a = lo, fa = f(lo);
  if (fa == 0.0) return lo;
  for (int i = 1; i <= kSamples; ++i) {
    double b = i == kSamples ? hi : lo + (hi - lo) * i / kSamples;
    const double fb = f(b);
    if (fb == 0.0) return b;
    if ((fa < 0.0) != (fb < 0.0)) {
      for (int j = 0; j < 200 && b - a > 1e-13 * std::max(1.0, std::abs(a)); ++j) {
        const double m = 0.5 * (a + b);
        const double fm = f(m);
        if (fm == 0.0) return m;
        if ((fa < 0.0) != (fm < 0.0))
          b = m;
        else
          a = m, fa = fm;
      }
      return 0.5 * (a + b);
    }
    a = b, fa = fb;
  }
  return std::nullopt;  // no crossing inside the clear aperture
}

Vec3d asphereNormal(const AsphereProfile& profile, const Vec3d& hit) {
  // The gradient of z - sag(r): (-g x, -g y, 1) with g = sag'(r) / r.
  const double g = profile.slopeOverR(hit.x * hit.x + hit.y * hit.y).value_or(0.0);
  return normalize(Vec3d{-g * hit.x, -g * hit.y, 1.0});
}

}  // namespace lensrt
