// The render-time scene: owns the Embree device and BVH built from a SceneDesc
// and answers ray queries. Thread-safe for concurrent queries after construction.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "core/ray.h"
#include "core/vec.h"
#include "scene/scene_desc.h"

// Embree's scene handle (embree3/rtcore.h), named here without its header.
struct RTCSceneTy;

namespace lensrt {

// Alpha: a material's alpha is baseColor factor * texture alpha * COLOR_0 alpha.
// AlphaMode::Mask cuts the surface out where alpha < alphaCutoff.
// AlphaMode::Blend is stochastic transparency: each ray passes through with
// probability 1 - alpha, decided by a hash of the world ray and the triangle,
// so the same ray always gets the same answer (renders stay bit-identical for
// a seed) and shadow rays see the same statistics as camera and bounce rays.

// Geometry at a ray hit, in world space. Material evaluation (textures, normal
// maps, BSDF) is the renderer's job; this is only what the geometry says.
struct SurfaceHit {
  float t = 0;
  Vec3f position;
  Vec3f geometricNormal;      // unit, from the triangle's winding (after the instance transform)
  Vec3f shadingNormal;        // unit, interpolated vertex normal (or geometric), same hemisphere as
                              // geometricNormal
  Vec4f tangent{0, 0, 0, 0};  // world xyz unit + handedness w; zero when the mesh has none
  Vec2f uv;                   // TEXCOORD_0, zero when absent
  // The hit in the mesh's own coordinates (its POSITION values, the glTF
  // node's frame), on the mesh at the shutter's opening.
  Vec3f objectPosition;
  Vec2f uv1;                // TEXCOORD_1, zero when absent
  Vec4f color{1, 1, 1, 1};  // COLOR_0 (linear RGBA), white when absent
  int material = -1;        // index into SceneDesc::materials, -1: default material
  int instance = -1;        // index into SceneDesc::instances
  unsigned primitive = 0;   // triangle index within the instance's mesh
  Vec2f barycentric;        // Embree's (u, v): the weights of the triangle's second and third corner
};

class RenderScene {
 public:
  // Throws InputError(desc.sourceFile, ...) for geometry Embree cannot take.
  explicit RenderScene(SceneDesc desc);
  ~RenderScene();
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  // Closest hit in (ray.tMin, ray.tMax); alpha-masked texels are skipped.
  std::optional<SurfaceHit> intersect(const Ray& ray) const;
  // True when anything blocks the segment (ray.tMin, ray.tMax).
  bool occluded(const Ray& ray) const;

  const SceneDesc& desc() const;
  Bounds3f bounds() const;

  // Ends the scene (its BVH is released) and hands over its description,
  // whose materials and textures the next frame of a sequence reuses. Only
  // destruction may follow.
  SceneDesc releaseDesc() &&;

  // How the instances were mapped onto Embree: meshes placed once are baked into
  // world space; meshes placed several times are one shared scene plus one
  // Embree instance per placement.
  struct Stats {
    int bakedGeometries = 0;
    int sharedMeshes = 0;
    int embreeInstances = 0;
    // Bytes Embree holds for this scene (BVHs and its copies of the
    // vertices and indices), from its memory monitor.
    std::int64_t embreeBytes = 0;
  };
  Stats stats() const;

  // The top-level Embree scene, for measuring tools that trace rays with
  // Embree alone (tools/bench); alpha filters stay attached.
  RTCSceneTy* embreeScene() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lensrt
