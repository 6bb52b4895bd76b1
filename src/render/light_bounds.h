// What a light tree knows of a light or a group of lights: where they are
// (a box), how much they emit (phi), and where they emit to (a cone of normals
// theta_o around an axis, widened by theta_e, the angle beyond a normal at
// which emission still reaches). After Conty Estevez and Kulla, "Importance
// Sampling of Many Lights with Adaptive Tree Splitting" (2018), as pbrt-v4's
// LightBounds uses it.
#pragma once

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
  float importance(const Vec3f& p, const Vec3f& n) const;

  Vec3f centre{0, 0, 0};
  float radius2 = 0;  // the bounding sphere's squared radius
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

}  // namespace lensrt
