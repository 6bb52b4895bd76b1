// KHR_materials_clearcoat's lobe: a white GGX reflection with the Schlick
// Fresnel of ior 1.5 (f0 = 0.04, f90 = 1), on the clearcoat's own normal and
// roughness. The layer under it is scaled by 1 - clearcoat E, E its
// directional albedo (see gltf_bsdf.h). Local frame: z = the coat's normal.
#pragma once

#include <optional>

#include "core/vec.h"
#include "render/bsdf.h"
#include "render/spectrum.h"

namespace lensrt {

class ClearcoatBsdf {
 public:
  explicit ClearcoatBsdf(float roughness);

  Spectrum eval(const Vec3f& wo, const Vec3f& wi) const;
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BsdfSample> sample(const Vec3f& wo, const Vec2f& u) const;
  float albedo(float mu) const;  // directional albedo at cos theta = mu

 private:
  float alpha_;
};

}  // namespace lensrt
