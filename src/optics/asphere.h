// Even aspheric surface profile: a conic of base curvature c = 1 / radius and
// conic constant k, plus polynomial terms A4 r^4 + A6 r^6 + ... + A16 r^16:
//
//   z(r) = c r^2 / (1 + sqrt(1 - (1 + k) c^2 r^2)) + sum_j A_{2j+4} r^{2j+4}
//
// (k = 0 sphere, -1 < k < 0 prolate ellipsoid, k = -1 paraboloid, k < -1
// hyperboloid, k > 0 oblate ellipsoid). The sag is only defined where the
// square root's argument is non-negative: r <= 1 / (|c| sqrt(1 + k)) when
// 1 + k > 0, everywhere otherwise. Paraxial analysis uses the base curvature
// alone (the conic and polynomial terms are of fourth order in r).
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace lensrt {

// A4, A6, ..., A16: seven even coefficients, in mm^(1 - 2j - 4).
inline constexpr int kAsphericTerms = 7;
using AsphericCoefficients = std::array<double, kAsphericTerms>;

struct AsphereProfile {
  double curvature = 0.0;  // 1 / radius, 0 for a flat base
  double conic = 0.0;
  AsphericCoefficients coefficients{};

  // Largest height at which the sag is defined (infinity when unbounded).
  double domainRadius() const {
    const double q = (1.0 + conic) * curvature * curvature;
    return q > 0.0 ? 1.0 / std::sqrt(q) : std::numeric_limits<double>::infinity();
  }
  // z(r) from r^2; nullopt outside the domain.
  std::optional<double> sag(double r2) const {
    const double arg = 1.0 - (1.0 + conic) * curvature * curvature * r2;
    if (!(arg >= 0.0)) return std::nullopt;
    return curvature * r2 / (1.0 + std::sqrt(arg)) + polynomial(r2);
  }
  // dz/dr divided by r (finite at r = 0), from r^2; nullopt outside the
  // domain and on its rim, where the slope is infinite.
  std::optional<double> slopeOverR(double r2) const {
    const double arg = 1.0 - (1.0 + conic) * curvature * curvature * r2;
    if (!(arg > 0.0)) return std::nullopt;
    double poly = 0.0, r2n = r2;  // sum (2j + 4) A_{2j+4} r^{2j+2}
    for (int j = 0; j < kAsphericTerms; ++j, r2n *= r2) poly += (2 * j + 4) * coefficients[j] * r2n;
    return curvature / std::sqrt(arg) + poly;
  }

 private:
  double polynomial(double r2) const {
    // Horner in r^2: r^4 (A4 + r^2 (A6 + ... ))
    double p = 0.0;
    for (int j = kAsphericTerms - 1; j >= 0; --j) p = p * r2 + coefficients[j];
    return p * r2 * r2;
  }
};

}  // namespace lensrt

#include "core/vec.h"

namespace lensrt {

// The first crossing t >= -1e-9 of the ray p + t d (p relative to the
// surface's vertex, d unit) with the aspheric surface inside the cylinder
// r <= rMax (rMax within the profile's domain, as validation ensures);
// nullopt when the ray misses the surface there. Newton's method on the sag,
// started from the base conic's exact hit, with a bracketing bisection when
// Newton leaves the cylinder or stalls; never returns a non-finite value.
std::optional<double> intersectAsphere(const AsphereProfile& profile, double rMax, const Vec3d& p,
                                       const Vec3d& d);
// Unit normal of the surface at a point (relative to the vertex) inside the
// domain, facing +z (toward the film).
Vec3d asphereNormal(const AsphereProfile& profile, const Vec3d& hit);

}  // namespace lensrt
