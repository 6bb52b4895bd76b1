// Every light the integrator samples for next-event estimation: emissive
// triangles (area lights), glTF punctual lights and the environment. One light
// is picked per estimate with probability proportional to an estimate of its
// power, then a point/direction on it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/vec.h"
#include "render/distribution.h"
#include "render/environment.h"
#include "render/material_eval.h"
#include "scene/scene_desc.h"

namespace lensrt {

struct LightSample {
  Vec3f wi;        // world, unit, from the shading point toward the light
  float distance;  // to the light point; infinity for the environment and directional lights
  Rgb radiance;    // arriving at the shading point along -wi, before the BRDF
  float pdf;       // solid angle (including the light pick); for delta lights the pick probability
  bool delta;      // point, spot, directional: no MIS with BSDF sampling
};

class LightSet {
 public:
  LightSet(const MaterialTable& materials, const Environment& environment, const Bounds3f& sceneBounds);

  bool empty() const { return pick_.empty(); }
  // The colour of the light with the most power (a punctual light, an
  // emissive material's triangles together, or the environment), for an
  // automatic white balance; none when the scene has no light.
  std::optional<Rgb> dominantColour() const { return dominantColour_; }
  std::size_t emissiveTriangleCount() const { return triangles_.size(); }

  std::optional<LightSample> sample(const Vec3f& p, float uPick, const Vec2f& u) const;

  // Solid-angle density with which sample() would have produced the hit on an
  // emissive triangle seen from p (for MIS when a BSDF ray hits an emitter).
  float pdfTriangle(int instance, unsigned primitive, const Vec3f& p, const Vec3f& lightPoint,
                    const Vec3f& lightNormal) const;
  float pdfEnvironment(const Vec3f& direction) const;

 private:
  struct Triangle {
    Vec3f p0, e1, e2;  // world space: p0 + b1 e1 + b2 e2
    Vec3f normal;      // unit, the front (glTF winding, corrected for mirroring)
    Vec2f uv0, uv1, uv2;
    float area;
    int material;
    int mesh;  // for the coverage of MASK and BLEND emitters
    unsigned prim;
  };
  std::optional<LightSample> sampleTriangle(const Triangle& t, const Vec3f& p, const Vec2f& u) const;
  std::optional<LightSample> samplePunctual(const PunctualLight& l, const Vec3f& p) const;

  const MaterialTable* materials_;
  const Environment* environment_;
  std::vector<Triangle> triangles_;
  std::vector<std::int64_t> instanceFirstTriangle_;  // -1: instance not emissive
  // Pick order: punctual lights, then triangles, then the environment.
  Distribution1D pick_;
  std::optional<Rgb> dominantColour_;
  std::size_t firstTriangle_ = 0, environmentIndex_ = 0;
};

// glTF KHR_lights_punctual spot cone: smooth falloff from the inner to the outer angle.
float spotAttenuation(const PunctualLight& light, const Vec3f& towardPoint);
// glTF range window: (clamp(1 - (d/range)^4))^2, 1 without range.
float rangeWindow(const PunctualLight& light, float distance);

}  // namespace lensrt
