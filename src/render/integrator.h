// Unidirectional path tracing: next-event estimation to one light per vertex
// plus BSDF sampling, combined by multiple importance sampling (power
// heuristic), Russian roulette on the path throughput.
#pragma once

#include "core/ray.h"
#include "core/vec.h"
#include "render/environment.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/ray_observer.h"
#include "render/sampler.h"
#include "render/wavelengths.h"
#include "scene/render_scene.h"

namespace lensrt {

struct IntegratorSettings {
  // Scattering events per path: 0 shows only emitters and the environment seen
  // directly, 1 adds direct lighting, and so on.
  int maxDepth = 8;
  // Russian roulette starts after this many bounces.
  int rouletteDepth = 3;
  // Sees every ray before it is traced (measuring tools only); not owned.
  RayObserver* observer = nullptr;
};

// One camera path's result: radiance and what the first hit says (for AOVs).
struct PathSample {
  Rgb radiance{0, 0, 0};  // in the film's RGB
  bool hit = false;
  // From the camera node's origin to the first hit (metres): the renderer
  // sets it from `position`, whatever the lens (integrator: along the ray).
  float distance = 0;
  float planarZ = 0;              // the first hit's depth along the camera's viewing axis (renderer)
  Vec3f position{0, 0, 0};        // the first hit, world space
  Vec3f objectPosition{0, 0, 0};  // the first hit in its mesh's coordinates (SurfaceHit)
  Vec2f uv{0, 0};                 // the first hit's TEXCOORD_0, zero when the mesh has none
  Vec3f normal{0, 0, 0};          // world shading normal at the first hit, facing the camera
  Rgb albedo{0, 0, 0};            // base colour at the first hit
  int instance = -1;              // the first hit's SceneDesc instance (-1: no hit)
  int material = -1;              // the first hit's material (-1: the default material)
  // The first hit's triangle and where on it (SurfaceHit's): the surface
  // point that optical flow follows to other moments (render/motion_flow.h).
  unsigned primitive = 0;
  Vec2f barycentric{0, 0};
};

class Integrator {
 public:
  Integrator(const RenderScene& scene, const MaterialTable& materials, const LightSet& lights,
             const Environment& environment, const IntegratorSettings& settings);

  // `ray` must have a unit direction; `lambda` says how the path carries
  // colour (RGB, or the sample's wavelengths). `afterLensReflection`: the
  // camera ray reflected in the lens (CameraRay::lensReflected), so the
  // emitters and the environment's sun that the flare light pass takes are
  // not counted where the ray meets them (they are, as they light the scene),
  // nor the still lamps' light on the surface the ray meets first.
  PathSample trace(const Ray& ray, const Sampler& sampler,
                   SampledWavelengths lambda = SampledWavelengths::rgb(),
                   bool afterLensReflection = false) const;
  // The sampler dimensions a camera path can use, camera's included (the
  // blocks it asks for; see PixelSeeds).
  std::uint32_t sampleDimensions() const;
  const RenderScene& scene() const { return scene_; }

 private:
  // What reaches a punctual light along a shadow ray: 1 when nothing is in
  // the way, 0 behind anything opaque or rough, and through smooth thin-walled
  // transmitting sheets (window panes) their straight-through share,
  // (1 - metallic) transmission (1 - F) times the base colour. A path can
  // reach a point light through a smooth sheet in no other way (neither BSDF
  // sampling nor next-event estimation at the sheet can aim along a spike at
  // a point), so this counts nothing twice. Through rough sheets (a paper
  // lamp shade) light arrives by next-event estimation at the sheet; area
  // lights and the sky keep opaque shadow rays and reach through glass by
  // BSDF sampling.
  // `target` is the light point (finite) for re-aiming past each sheet.
  Spectrum thinGlassTransmittance(Ray ray, const Vec3f& target, bool finite,
                                  const SampledWavelengths& lambda) const;

  const RenderScene& scene_;
  const MaterialTable& materials_;
  const LightSet& lights_;
  const Environment& environment_;
  IntegratorSettings settings_;
  bool thinGlass_ = false;  // the scene has thin-walled transmitting materials
};

float powerHeuristic(float pdfA, float pdfB);

}  // namespace lensrt
