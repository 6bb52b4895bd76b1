#include "render/light_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"

namespace lensrt {
namespace {

using lightBoundsDetail::sinFromCos;

float angleBetween(const Vec3f& a, const Vec3f& b) {
  // Accurate for nearly parallel and nearly opposite vectors alike (acos is not).
  const float d = dot(a, b);
  return d < 0 ? kPiF - 2 * std::asin(std::min(1.0f, 0.5f * length(a + b)))
               : 2 * std::asin(std::min(1.0f, 0.5f * length(a - b)));
}

}  // namespace

float LightBounds::importance(const Vec3f& p, const Vec3f& n) const {
  return phi > 0 ? ImportanceBounds(*this).importance(p, n) : 0.0f;
}

ImportanceBounds::ImportanceBounds(const LightBounds& b)
    : centre(b.bounds.center()),
      radius2(0.25f * lengthSquared(b.bounds.diagonal())),
      radius(std::sqrt(radius2)),
      phi(b.phi),
      axis(b.axis),
      cosThetaO(b.cosThetaO),
      sinThetaO(sinFromCos(b.cosThetaO)),
      cosThetaE(b.cosThetaE),
      twoSided(b.twoSided) {}

ImportancePair::ImportancePair(const ImportanceBounds& a, const ImportanceBounds& b) {
  const auto both = [](Lanes& lanes, float x, float y) { lanes = {x, y, x, y}; };
  both(cx, a.centre.x, b.centre.x);
  both(cy, a.centre.y, b.centre.y);
  both(cz, a.centre.z, b.centre.z);
  both(radius2, a.radius2, b.radius2);
  both(radius, a.radius, b.radius);
  both(phi, a.phi, b.phi);
  both(ax, a.axis.x, b.axis.x);
  both(ay, a.axis.y, b.axis.y);
  both(az, a.axis.z, b.axis.z);
  both(cosThetaO, a.cosThetaO, b.cosThetaO);
  both(sinThetaO, a.sinThetaO, b.sinThetaO);
  both(cosThetaE, a.cosThetaE, b.cosThetaE);
  const std::int32_t sidesA = a.twoSided ? -1 : 0, sidesB = b.twoSided ? -1 : 0;
  twoSided = {sidesA, sidesB, sidesA, sidesB};
}

ImportanceBounds ImportancePair::bounds(int k) const {
  const std::size_t i = std::size_t(k);
  ImportanceBounds b;
  b.centre = {cx[i], cy[i], cz[i]};
  b.radius2 = radius2[i];
  b.radius = radius[i];
  b.phi = phi[i];
  b.axis = {ax[i], ay[i], az[i]};
  b.cosThetaO = cosThetaO[i];
  b.sinThetaO = sinThetaO[i];
  b.cosThetaE = cosThetaE[i];
  b.twoSided = twoSided[i] != 0;
  return b;
}

LightBounds unite(const LightBounds& a, const LightBounds& b) {
  if (!(a.phi > 0)) return b;
  if (!(b.phi > 0)) return a;
  LightBounds u;
  u.bounds = a.bounds;
  u.bounds.extend(b.bounds);
  u.phi = a.phi + b.phi;
  u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
  u.twoSided = a.twoSided || b.twoSided;

  // The cones: one inside the other, else the cone from a's far edge to b's.
  // First the cases without trigonometry (a tree's build unites often).
  if (a.cosThetaO <= -1 || b.cosThetaO <= -1) {
    u.axis = a.cosThetaO <= -1 ? a.axis : b.axis;
    u.cosThetaO = -1;
    return u;
  }
  if (a.axis == b.axis) {
    u.axis = a.axis;
    u.cosThetaO = std::min(a.cosThetaO, b.cosThetaO);
    return u;
  }
  // One direction (a triangle's normal) inside the other cone.
  if (b.cosThetaO >= 1 && dot(a.axis, b.axis) >= a.cosThetaO) {
    u.axis = a.axis;
    u.cosThetaO = a.cosThetaO;
    return u;
  }
  if (a.cosThetaO >= 1 && dot(a.axis, b.axis) >= b.cosThetaO) {
    u.axis = b.axis;
    u.cosThetaO = b.cosThetaO;
    return u;
  }
  const float thetaA = std::acos(std::clamp(a.cosThetaO, -1.0f, 1.0f));
  const float thetaB = std::acos(std::clamp(b.cosThetaO, -1.0f, 1.0f));
  const float thetaD = angleBetween(a.axis, b.axis);
  if (std::min(thetaD + thetaB, kPiF) <= thetaA) {
    u.axis = a.axis;
    u.cosThetaO = a.cosThetaO;
    return u;
  }
  if (std::min(thetaD + thetaA, kPiF) <= thetaB) {
    u.axis = b.axis;
    u.cosThetaO = b.cosThetaO;
    return u;
  }
  const float thetaO = 0.5f * (thetaA + thetaD + thetaB);
  const Vec3f turnAxis = cross(a.axis, b.axis);
  const float turnLength = length(turnAxis);
  if (thetaO >= kPiF || !(turnLength > 0)) {
    u.axis = a.axis;
    u.cosThetaO = -1;
    return u;
  }
  // Turn a's axis toward b's by thetaO - thetaA (Rodrigues' formula; the
  // turning axis is perpendicular to a's).
  const float turn = thetaO - thetaA;
  const Vec3f k = turnAxis / turnLength;
  u.axis = normalize(a.axis * std::cos(turn) + cross(k, a.axis) * std::sin(turn));
  u.cosThetaO = std::cos(thetaO);
  return u;
}

float orientationMeasure(float cosThetaO, float cosThetaE) {
  // The two common cases in closed form (a build evaluates this often): all
  // directions, 4 pi; one normal with a Lambertian spread, pi.
  if (cosThetaO <= -1) return 4 * kPiF;
  if (cosThetaO >= 1 && cosThetaE == 0) return kPiF;
  const float thetaO = std::acos(std::clamp(cosThetaO, -1.0f, 1.0f));
  const float thetaE = std::acos(std::clamp(cosThetaE, -1.0f, 1.0f));
  const float thetaW = std::min(thetaO + thetaE, kPiF);
  const float sinThetaO = sinFromCos(cosThetaO);
  return 2 * kPiF * (1 - cosThetaO) +
         0.5f * kPiF *
             (2 * thetaW * sinThetaO - std::cos(thetaO - 2 * thetaW) - 2 * thetaO * sinThetaO + cosThetaO);
}

}  // namespace lensrt
