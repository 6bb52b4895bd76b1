// The transmission lobe of glTF's KHR_materials_transmission: a rough
// dielectric interface (GGX, the microfacet model of the reflection; Walter
// et al. 2007 with visible-normal sampling) that reflects the exact
// unpolarised Fresnel fraction F and refracts the rest, tinted by the base
// colour. Total internal reflection follows from F = 1.
// Thin-walled (glTF's default without KHR_materials_volume): the surface is
// an infinitely thin sheet, so transmitted light keeps its direction (the
// mirror image of the reflection lobe through the surface plane).
// Local frame: z = the shading normal on wo's side; wo.z > 0. Values are for
// radiance transport (the refracted lobe carries pbrt's 1 / eta^2).
#pragma once

#include <optional>

#include "core/vec.h"
#include "render/bsdf.h"
#include "render/spectrum.h"

namespace lensrt {

// Exact unpolarised Fresnel reflectance of a dielectric interface for light
// arriving at cosI (>= 0) from the medium of index 1 into relative index eta.
float fresnelDielectric(float cosI, float eta);

struct DielectricParams {
  // Index of the far side over the near side (wo's): ior entering the
  // material, 1 / ior leaving it. Thin-walled surfaces use ior both ways.
  float eta = 1.5f;
  float roughness = 0.0f;        // perceptual, as the glTF material's
  Spectrum tint{1.0f};           // transmission colour (glTF: the base colour)
  float specularWeight = 1.0f;   // KHR_materials_specular: scales F
  Spectrum specularColor{1.0f};  // KHR_materials_specular: tints the reflection
  bool thin = false;
};

class DielectricBsdf {
 public:
  explicit DielectricBsdf(const DielectricParams& p);

  Spectrum eval(const Vec3f& wo, const Vec3f& wi) const;
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  // uLobe chooses reflection or transmission (by the Fresnel term at the
  // sampled microfacet), u the microfacet.
  std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, const Vec2f& u) const;
  // Expected fraction reflected rather than transmitted for wo (lobe choice).
  float reflectance(const Vec3f& wo) const;
  float alpha() const { return alpha_; }

 private:
  // Scalar reflect weight at a microfacet (w * F) and its coloured value.
  float reflectWeight(float cosOH) const;
  DielectricParams p_;
  float alpha_;
};

}  // namespace lensrt
