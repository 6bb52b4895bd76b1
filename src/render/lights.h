// Every light the integrator samples for next-event estimation: emissive
// triangles (area lights), glTF punctual lights and the environment. One light
// is picked per estimate, then a point/direction on it. The pick is by a light
// tree that adapts to the shading point (LightSampling::Tree), or by an
// estimate of each light's power alone (LightSampling::Power).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "core/vec.h"
#include "render/distribution.h"
#include "render/environment.h"
#include "render/light_tree.h"
#include "render/material_eval.h"
#include "scene/scene_desc.h"

namespace lensrt {

struct LightSample {
  Vec3f wi;        // world, unit, from the shading point toward the light
  float distance;  // to the light point; infinity for the environment and directional lights
  Rgb radiance;    // arriving at the shading point along -wi, before the BRDF
  float pdf;       // solid angle (including the light pick); for delta lights the pick probability
  bool delta;      // point, spot, directional: no MIS with BSDF sampling
  // A lamp (isFlareLamp): lens flare's light pass takes its light on the
  // surfaces a lens-reflected camera ray meets first.
  bool flareLamp = false;
};

// A point or spot light that stays still during the shutter: the lights
// whose light on the scene the flare light pass sends through the lens
// (render/flare_light_pass.h), as it has no time.
bool isFlareLamp(const PunctualLight& light);

// How a light is picked (--light-sampler).
//  Tree:  the lights with a place (point and spot lights, emissive triangles)
//         by a LightTree, for each shading point; directional lights and the
//         environment, which have none, stay outside it, each picked with a
//         fixed probability, its share of the power (the tree's share is that
//         of its lights together).
//  Power: every light by its power alone, wherever the shading point is.
enum class LightSampling { Tree, Power };
const char* lightSamplingName(LightSampling sampling);  // "tree", "power"
std::optional<LightSampling> parseLightSampling(std::string_view name);

class LightSet {
 public:
  LightSet(const MaterialTable& materials, const Environment& environment, const Bounds3f& sceneBounds,
           LightSampling sampling = LightSampling::Tree);

  bool empty() const { return pick_.empty(); }
  // The colour of the light with the most power (a punctual light, an
  // emissive material's triangles together, or the environment), for an
  // automatic white balance; none when the scene has no light.
  std::optional<Rgb> dominantColour() const { return dominantColour_; }
  std::size_t emissiveTriangleCount() const { return triangles_.size(); }

  LightSampling sampling() const { return sampling_; }

  // A light sample for the shading point p with shading normal n (zero when
  // it has none): the pick from uPick, the point on the light from u.
  // `time`: the path's (Ray::time), where moving lights are (motion blur).
  std::optional<LightSample> sample(const Vec3f& p, const Vec3f& n, float uPick, const Vec2f& u,
                                    float time = 0.0f) const;

  // Solid-angle density with which sample(p, n, ...) would have produced the
  // hit on an emissive triangle (for MIS when a BSDF ray hits an emitter).
  float pdfTriangle(int instance, unsigned primitive, const Vec3f& p, const Vec3f& n, const Vec3f& lightPoint,
                    const Vec3f& lightNormal, float time = 0.0f) const;
  // The same for the environment in `direction` (its pick does not depend
  // on the point).
  float pdfEnvironment(const Vec3f& direction) const;
  // The probability that sample(p, n, ...) picks light i: punctual lights
  // first (scene order), then emissive triangles, then the environment.
  float pickProbability(std::size_t i, const Vec3f& p, const Vec3f& n) const;
  std::size_t lightCount() const { return pick_.size(); }

  // Lens flare's light pass (render/flare_light_pass.h) takes the lens
  // reflections of every emissive triangle that stays still during the
  // shutter (the pass has no time: a moving one is left to camera paths),
  // and camera paths skip those after a lens reflection.
  bool stillEmitter(int instance, unsigned primitive) const;
  // Emissive triangle t (0 <= t < emissiveTriangleCount()) where it is at
  // the shutter's opening, for the pass's choice of triangles.
  struct EmissiveTriangle {
    Vec3f p0, e1, e2;  // world space
    Vec3f normal;      // unit, the front
    float area = 0;
    float luminance = 0;  // of the emissive factor (textures only dim it)
    bool twoSided = false;
    bool still = true;
    int instance = -1;  // SceneDesc::instances
  };
  EmissiveTriangle emissiveTriangle(std::size_t t) const;
  // A point uniform on emissive triangle t (at the opening) seen from p: as
  // sample() gives it, without the pick (pdf per solid angle at p).
  std::optional<LightSample> sampleEmissiveTriangle(std::size_t t, const Vec3f& p, const Vec2f& u) const {
    return sampleTriangle(triangles_[t], p, u);
  }

 private:
  struct Triangle {
    Vec3f p0, e1, e2;  // world space: p0 + b1 e1 + b2 e2
    Vec3f normal;      // unit, the front (glTF winding, corrected for mirroring)
    Vec2f uv0, uv1, uv2;
    float area;
    int material;
    int mesh;  // for the coverage of MASK and BLEND emitters
    int instance;
    unsigned prim;
    float handed;                      // -1 when the placement mirrors (the front flips)
    std::size_t firstStep = kNoSteps;  // a moving triangle's steps in steps_
  };
  // A moving triangle's corners at one motion step.
  struct TriangleStep {
    Vec3f p0, e1, e2;
  };
  static constexpr std::size_t kNoSteps = std::size_t(-1);
  // The triangle, or the light, where it is at `time` (linear between steps, as Embree moves geometry).
  Triangle posed(const Triangle& t, float time) const;
  PunctualLight posed(const PunctualLight& l, float time) const;
  std::optional<LightSample> sampleTriangle(const Triangle& t, const Vec3f& p, const Vec2f& u) const;
  std::optional<LightSample> samplePunctual(const PunctualLight& l, const Vec3f& p) const;
  void buildTree(const std::vector<float>& power);

  const MaterialTable* materials_;
  const Environment* environment_;
  std::vector<Triangle> triangles_;
  std::vector<TriangleStep> steps_;  // motionSteps_ per moving triangle
  std::size_t motionSteps_ = 0;
  std::vector<std::int64_t> instanceFirstTriangle_;  // -1: instance not emissive
  // Pick order: punctual lights, then triangles, then the environment.
  Distribution1D pick_;
  LightSampling sampling_;
  // Tree sampling: the lights outside the tree (directional ones and the
  // environment), then the tree as a whole, by power; `outside_` maps the
  // first of them to light indices.
  Distribution1D top_;
  std::vector<std::size_t> outside_;
  std::vector<std::size_t> topSlot_;  // light index -> its slot in top_ (outside lights only)
  LightTree tree_;                    // over light indices; outside lights have no leaf
  std::optional<Rgb> dominantColour_;
  std::size_t firstTriangle_ = 0, environmentIndex_ = 0;
};

// glTF KHR_lights_punctual spot cone: smooth falloff from the inner to the outer angle.
float spotAttenuation(const PunctualLight& light, const Vec3f& towardPoint);
// glTF range window: (clamp(1 - (d/range)^4))^2, 1 without range.
float rangeWindow(const PunctualLight& light, float distance);

}  // namespace lensrt
