// Material evaluation at a ray hit: textures times factors, normal mapping,
// emission. Produces the BSDF parameters and the shading frame.
#pragma once

#include <vector>

#include "core/frame.h"
#include "core/vec.h"
#include "render/gltf_bsdf.h"
#include "render/wavelengths.h"
#include "scene/render_scene.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The render-time view of the scene's materials, with the parameters glTF
// extensions may add on top of scene_desc's Material (index -1 is glTF's
// default material: white, metallic 1, roughness 1).
class MaterialTable {
 public:
  struct Extra {
    float specularWeight = 1.0f;  // KHR_materials_specular strength
  };

  explicit MaterialTable(const SceneDesc& scene);

  const Material& material(int index) const;
  const Extra& extra(int index) const;
  Extra& extra(int index);  // for tests and future extensions
  const SceneDesc& scene() const { return *scene_; }

 private:
  const SceneDesc* scene_;
  Material default_;
  std::vector<Extra> extras_;  // [0] is the default material, then materials + 1
};

struct ShadingPoint {
  Frame frame;              // z = (normal-mapped) shading normal, facing the viewer
  Frame coatFrame;          // z = the clearcoat's normal, facing the viewer
  Vec3f geometricNormal;    // unit, facing the viewer
  bool frontFace = true;    // the viewer is on the side the triangle's winding faces
  GltfBsdfParams bsdf;      // colours at the sample's wavelengths
  Rgb albedo{0, 0, 0};      // the base colour in RGB (the albedo AOV)
  Spectrum emission{0.0f};  // radiance leaving toward the viewer
};

// A volume whose index depends on the wavelength (KHR_materials_dispersion):
// a spectral path goes on at its hero wavelength alone from there.
bool isDispersiveVolume(const Material& m);

// Whether light arriving from wi (unit, world) can scatter at `sp` by
// `bsdf`: from the geometric normal's front unless the BSDF transmits, and on
// the same side of the geometric and the shading normal (otherwise a
// reflection would pass through the surface or a refraction stay in front).
inline bool receivesLight(const ShadingPoint& sp, const GltfBsdf& bsdf, const Vec3f& wi) {
  const bool above = dot(wi, sp.geometricNormal) > 0;
  return (above || bsdf.transmits()) && above == (dot(wi, sp.frame.n) > 0);
}

// wo: unit world direction toward the viewer. The colours are turned into
// `lambda`'s spectra (RGB transport keeps them).
ShadingPoint evaluateMaterial(const MaterialTable& materials, const SurfaceHit& hit, const Vec3f& wo,
                              const SampledWavelengths& lambda = SampledWavelengths::rgb());

// Emitted radiance of a material at a point with UV sets uv0 and uv1 leaving a
// surface whose winding normal makes cosine `cosFront` with the direction of
// travel (front-face emission only unless the material is double sided).
Rgb emittedRadiance(const MaterialTable& materials, int material, const Vec2f& uv0, const Vec2f& uv1,
                    float cosFront);

}  // namespace lensrt
