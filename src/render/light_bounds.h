// What a light tree knows of a light or a group of lights: where they are
// (a box), how much they emit (phi), and where they emit to (a cone of normals
// theta_o around an axis, widened by theta_e, the angle beyond a normal at
// which emission still reaches). After Conty Estevez and Kulla, "Importance
// Sampling of Many Lights with Adaptive Tree Splitting" (2018), as pbrt-v4's
// LightBounds uses it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__))
#include <xmmintrin.h>
#define LENSRT_IMPORTANCE_SSE 1
#endif

#include "core/bounds.h"
#include "core/vec.h"

namespace lensrt {

struct LightBounds {
  Bounds3f bounds;
  float phi = 0;          // emitted power (any unit shared by the lights of one tree); 0: no light
  Vec3f axis{0, 0, 1};    // unit, the cone's centre direction
  float cosThetaO = 1;    // the cone of normals: 1 for one direction, -1 for all
  float cosThetaE = 0;    // emission spread past the cone: 0 (pi/2) for a Lambertian emitter
  bool twoSided = false;  // emits along -axis as well

  // A conservative estimate of the light these lights can send to a point p
  // with normal n (zero: no normal, as in a volume). Zero only when none of
  // them can light p: the tree never picks a light that could contribute
  // with probability 0, so next-event estimation stays unbiased.
  float importance(const Vec3f& p, const Vec3f& n) const;
};

// What LightBounds::importance reads, with what it would compute from the
// box and the cone each time computed once: a light tree evaluates it for
// both children at every level of every walk. The same arithmetic, so the
// same bits as LightBounds::importance.
struct ImportanceBounds {
  ImportanceBounds() = default;
  explicit ImportanceBounds(const LightBounds& b);
  // LightBounds::importance for phi > 0 (inline: the tree's walk is hot).
  float importance(const Vec3f& p, const Vec3f& n) const;

  Vec3f centre{0, 0, 0};
  float radius2 = 0;  // the bounding sphere's squared radius
  float radius = 0;
  float phi = 0;
  Vec3f axis{0, 0, 1};
  float cosThetaO = 1, sinThetaO = 0, cosThetaE = 0;
  bool twoSided = false;
};

// Bounds of both: the box around both boxes, the power added, the smallest
// cone found around both cones (not always the smallest possible).
LightBounds unite(const LightBounds& a, const LightBounds& b);

// The orientation measure M_Omega of Conty Estevez and Kulla: the solid angle
// the cone and its spread cover, weighted by the cosine falloff. The tree's
// split cost multiplies it with phi and the box's surface area.
float orientationMeasure(float cosThetaO, float cosThetaE);

namespace lightBoundsDetail {
inline float sinFromCos(float c) {
  return std::sqrt(std::max(0.0f, 1 - c * c));
}
// cos(max(0, a - b)) for angles a and b in [0, pi] given by their sines and
// cosines (no inverse trigonometry on the hot path).
inline float cosOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
  return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
}  // namespace lightBoundsDetail

inline float ImportanceBounds::importance(const Vec3f& p, const Vec3f& n) const {
  // pbrt-v4's LightBounds::Importance, arranged to skip square roots and
  // divisions where an angle is known (a point has no extent; inside a cone
  // nothing is left of an angle): a tree walk evaluates it twice per level.
  const Vec3f fromLight = p - centre;
  const float dist2 = lengthSquared(fromLight);
  // A point close to (or inside) a large node must not get an importance
  // that grows without bound; nor may a point at a point light divide by 0.
  const float d2 = std::max({dist2, radius2, 1e-12f});
  const float dist = std::sqrt(dist2);
  const float invDist = dist > 0 ? 1 / dist : 0;
  const Vec3f wi = dist > 0 ? fromLight * invDist : Vec3f{0, 0, 1};

  // theta_b: the half-angle of the bounding sphere seen from p (all of the
  // sphere when p is inside it).
  float cosThetaB = -1, sinThetaB = 0;
  if (dist2 > radius2) {
    cosThetaB = 1;
    if (radius > 0) {
      sinThetaB = std::min(1.0f, radius * invDist);
      cosThetaB = lightBoundsDetail::sinFromCos(sinThetaB);
    }
  }
  // theta_w: from the cone's axis to p; theta_x what the cone of normals
  // leaves of it; theta_p what the bounding sphere's extent leaves then.
  float cosThetaW = dot(axis, wi);
  if (twoSided) cosThetaW = std::abs(cosThetaW);
  float cosThetaX = 1, sinThetaX = 0;
  if (!(cosThetaW > cosThetaO)) {
    const float sinThetaW = lightBoundsDetail::sinFromCos(cosThetaW);
    cosThetaX = cosThetaW * cosThetaO + sinThetaW * sinThetaO;
    sinThetaX = sinThetaW * cosThetaO - cosThetaW * sinThetaO;
  }
  const float cosThetaP =
      lightBoundsDetail::cosOfClampedDifference(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
  if (cosThetaP <= cosThetaE) return 0;
  float result = phi * cosThetaP / d2;
  if (n.x != 0 || n.y != 0 || n.z != 0) {
    // The receiver's cosine, at its most over the sphere; either side of the
    // surface, as a transmitting surface takes light from both.
    const float cosThetaI = std::abs(dot(wi, n));
    if (sinThetaB == 0) {
      if (cosThetaB > 0) result *= cosThetaI;  // a point: its own cosine (inside the sphere: any, 1)
    } else if (!(cosThetaI > cosThetaB)) {
      result *= cosThetaI * cosThetaB + lightBoundsDetail::sinFromCos(cosThetaI) * sinThetaB;
    }
  }
  // Finite, so that two children's importances always add up.
  return std::clamp(result, 0.0f, std::numeric_limits<float>::max());
}

// Two ImportanceBounds as importancePair reads them: each value of the two
// side by side (lanes 0 and 1, again in 2 and 3), so that a value of both is
// one load. The tree keeps one per inner node, for its children.
struct ImportancePair {
  ImportancePair() = default;
  ImportancePair(const ImportanceBounds& a, const ImportanceBounds& b);
  // ImportanceBounds k (0 or 1) back.
  ImportanceBounds bounds(int k) const;

  using Lanes = std::array<float, 4>;
  alignas(16) Lanes cx{}, cy{}, cz{}, radius2{}, radius{}, phi{};
  alignas(16) Lanes ax{}, ay{}, az{}, cosThetaO{}, sinThetaO{}, cosThetaE{};
  alignas(16) std::array<std::int32_t, 4> twoSided{};  // all bits set where two-sided
};

// importance() of both bounds of a pair for one point: the light tree's walk
// weighs both children at every level. Lane by lane in SSE registers the same
// operations in the same order as importance() (its branches become
// selects), so the same bits; elsewhere the two calls.
#if LENSRT_IMPORTANCE_SSE
namespace lightBoundsDetail {
using F4 = float __attribute__((vector_size(16)));
using M4 = std::int32_t __attribute__((vector_size(16)));
inline F4 splat(float x) {
  return F4{x, x, x, x};
}
inline F4 load(const ImportancePair::Lanes& a) {
  F4 v;
  std::memcpy(&v, a.data(), sizeof v);
  return v;
}
inline F4 select(M4 m, F4 x, F4 y) {
  return (F4)(((M4)x & m) | ((M4)y & ~m));
}
inline F4 sqrt(F4 x) {
  return (F4)_mm_sqrt_ps((__m128)x);
}
inline F4 abs(F4 x) {
  return (F4)((M4)x & M4{0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff});
}
// sinFromCos: std::max(0.0f, v) is (0 < v ? v : 0).
inline F4 sinFromCos(F4 c) {
  const F4 v = splat(1) - c * c;
  return sqrt(select(splat(0) < v, v, splat(0)));
}
}  // namespace lightBoundsDetail

inline std::array<float, 2> importancePair(const ImportancePair& b, const Vec3f& p, const Vec3f& n) {
  using namespace lightBoundsDetail;
  const F4 zero = splat(0), one = splat(1);
  const F4 fx = splat(p.x) - load(b.cx), fy = splat(p.y) - load(b.cy), fz = splat(p.z) - load(b.cz);
  const F4 dist2 = fx * fx + fy * fy + fz * fz;
  const F4 radius2 = load(b.radius2), radius = load(b.radius);
  // std::max({dist2, radius2, 1e-12f}): the first of the largest.
  F4 d2 = select(dist2 < radius2, radius2, dist2);
  d2 = select(d2 < splat(1e-12f), splat(1e-12f), d2);
  const F4 dist = sqrt(dist2);
  const M4 positive = dist > zero;
  const F4 invDist = select(positive, one / dist, zero);
  const F4 wx = select(positive, fx * invDist, zero), wy = select(positive, fy * invDist, zero),
           wz = select(positive, fz * invDist, one);
  // theta_b; std::min(1.0f, s) is (s < 1 ? s : 1).
  const M4 outside = dist2 > radius2, extended = outside & (radius > zero);
  const F4 s = radius * invDist;
  const F4 sinThetaB = select(extended, select(s < one, s, one), zero);
  const F4 cosThetaB = select(outside, select(extended, sinFromCos(sinThetaB), one), splat(-1));
  // theta_w, theta_x, theta_p.
  F4 cosThetaW = load(b.ax) * wx + load(b.ay) * wy + load(b.az) * wz;
  M4 twoSided;
  std::memcpy(&twoSided, b.twoSided.data(), sizeof twoSided);
  cosThetaW = select(twoSided, abs(cosThetaW), cosThetaW);
  const F4 cosThetaO = load(b.cosThetaO), sinThetaO = load(b.sinThetaO);
  const M4 inCone = cosThetaW > cosThetaO;
  const F4 sinThetaW = sinFromCos(cosThetaW);
  const F4 cosThetaX = select(inCone, one, cosThetaW * cosThetaO + sinThetaW * sinThetaO);
  const F4 sinThetaX = select(inCone, zero, sinThetaW * cosThetaO - cosThetaW * sinThetaO);
  const F4 cosThetaP = select(cosThetaX > cosThetaB, one, cosThetaX * cosThetaB + sinThetaX * sinThetaB);
  F4 result = load(b.phi) * cosThetaP / d2;
  if (n.x != 0 || n.y != 0 || n.z != 0) {
    // The receiver's cosine; a factor of 1 where importance() multiplies by nothing.
    const F4 cosThetaI = abs(wx * splat(n.x) + wy * splat(n.y) + wz * splat(n.z));
    const F4 point = select(cosThetaB > zero, cosThetaI, one);
    const F4 extent =
        select(cosThetaI > cosThetaB, one, cosThetaI * cosThetaB + sinFromCos(cosThetaI) * sinThetaB);
    result = result * select(sinThetaB == zero, point, extent);
  }
  // std::clamp(result, 0, max) is (v < 0 ? 0 : max < v ? max : v); 0 outside the emission.
  const F4 largest = splat(std::numeric_limits<float>::max());
  result = select(result < zero, zero, select(largest < result, largest, result));
  result = select(cosThetaP <= load(b.cosThetaE), zero, result);
  return {result[0], result[1]};
}
#else
inline std::array<float, 2> importancePair(const ImportancePair& b, const Vec3f& p, const Vec3f& n) {
  return {b.bounds(0).importance(p, n), b.bounds(1).importance(p, n)};
}
#endif

}  // namespace lensrt
