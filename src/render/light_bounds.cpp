#include "render/light_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"

namespace lensrt {
namespace {

float sinFromCos(float c) {
  return std::sqrt(std::max(0.0f, 1 - c * c));
}

// cos and sin of max(0, a - b), for angles a and b in [0, pi] given by their
// sines and cosines (no inverse trigonometry on the hot path).
float cosOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
float sinOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

float angleBetween(const Vec3f& a, const Vec3f& b) {
  // Accurate for nearly parallel and nearly opposite vectors alike (acos is not).
  const float d = dot(a, b);
  return d < 0 ? kPiF - 2 * std::asin(std::min(1.0f, 0.5f * length(a + b)))
               : 2 * std::asin(std::min(1.0f, 0.5f * length(a - b)));
}

}  // namespace

float LightBounds::importance(const Vec3f& p, const Vec3f& n) const {
  return ImportanceBounds(*this).importance(p, n);
}

ImportanceBounds::ImportanceBounds(const LightBounds& b)
    : centre(b.bounds.center()),
      radius2(0.25f * lengthSquared(b.bounds.diagonal())),
      phi(b.phi),
      axis(b.axis),
      cosThetaO(b.cosThetaO),
      sinThetaO(sinFromCos(b.cosThetaO)),
      cosThetaE(b.cosThetaE),
      twoSided(b.twoSided) {}

float ImportanceBounds::importance(const Vec3f& p, const Vec3f& n) const {
  if (!(phi > 0)) return 0;
  const Vec3f fromLight = p - centre;
  const float dist2 = lengthSquared(fromLight);
  // A point close to (or inside) a large node must not get an importance
  // that grows without bound; nor may a point at a point light divide by 0.
  const float d2 = std::max({dist2, radius2, 1e-12f});
  const float dist = std::sqrt(dist2);
  const Vec3f wi = dist > 0 ? fromLight / dist : Vec3f{0, 0, 1};

  // theta_b: the half-angle of the bounding sphere seen from p (all of the
  // sphere when p is inside it).
  float cosThetaB = -1, sinThetaB = 0;
  if (dist2 > radius2) {
    const float sin2 = radius2 / dist2;
    cosThetaB = std::sqrt(std::max(0.0f, 1 - sin2));
    sinThetaB = std::sqrt(sin2);
  }
  // theta_w: from the cone's axis to p; theta_x what the cone of normals
  // leaves of it; theta_p what the bounding sphere's extent leaves then.
  float cosThetaW = dot(axis, wi);
  if (twoSided) cosThetaW = std::abs(cosThetaW);
  const float sinThetaW = sinFromCos(cosThetaW);
  const float cosThetaX = cosOfClampedDifference(sinThetaW, cosThetaW, sinThetaO, cosThetaO);
  const float sinThetaX = sinOfClampedDifference(sinThetaW, cosThetaW, sinThetaO, cosThetaO);
  const float cosThetaP = cosOfClampedDifference(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
  if (cosThetaP <= cosThetaE) return 0;
  float result = phi * cosThetaP / d2;
  if (n.x != 0 || n.y != 0 || n.z != 0) {
    // The receiver's cosine, at its most over the sphere; either side of the
    // surface, as a transmitting surface takes light from both.
    const float cosThetaI = std::abs(dot(wi, n));
    const float sinThetaI = sinFromCos(cosThetaI);
    result *= cosOfClampedDifference(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
  }
  // Finite, so that two children's importances always add up.
  return std::clamp(result, 0.0f, std::numeric_limits<float>::max());
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
  const float thetaO = std::acos(std::clamp(cosThetaO, -1.0f, 1.0f));
  const float thetaE = std::acos(std::clamp(cosThetaE, -1.0f, 1.0f));
  const float thetaW = std::min(thetaO + thetaE, kPiF);
  const float sinThetaO = sinFromCos(cosThetaO);
  return 2 * kPiF * (1 - cosThetaO) +
         0.5f * kPiF *
             (2 * thetaW * sinThetaO - std::cos(thetaO - 2 * thetaW) - 2 * thetaO * sinThetaO + cosThetaO);
}

}  // namespace lensrt
