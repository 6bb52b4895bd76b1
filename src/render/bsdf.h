// The glTF 2.0 metallic-roughness BRDF (spec appendix B): Lambert diffuse
// under a GGX specular layer for dielectrics (Schlick Fresnel, f0 = 0.04, or
// as KHR_materials_ior and KHR_materials_specular set it), GGX with a
// base-colour Schlick Fresnel for metals, blended by `metallic`.
// One departure, for energy conservation: the diffuse under the dielectric
// layer is weighted by the layer's directional albedo on both sides (Kelemen
// and Szirmay-Kalos) instead of glTF's 1 - F(v.h), which reflects more than it
// receives at grazing angles.
// Specular uses the height-correlated Smith masking-shadowing term and is
// sampled from the distribution of visible normals (Heitz 2018).
//
// All directions are in the local shading frame (z = shading normal), unit
// length, pointing away from the surface. Reflection only: both directions must
// be above the surface, otherwise the BRDF is zero.
#pragma once

#include <optional>

#include "core/vec.h"
#include "render/ggx.h"
#include "render/spectrum.h"

namespace lensrt {

struct BsdfParams {
  Spectrum baseColor{1.0f};
  float metallic = 1.0f;
  float roughness = 1.0f;  // perceptual; GGX alpha = roughness^2
  // KHR_materials_specular's strength of the dielectric specular layer: 1 is
  // plain glTF, 0 leaves a pure Lambertian dielectric (used by furnace tests).
  float specularWeight = 1.0f;
  Spectrum specularColor{1.0f};  // KHR_materials_specular's f0 tint
  float ior = 1.5f;              // KHR_materials_ior: f0 = ((ior - 1) / (ior + 1))^2
  // Share of the dielectric part that is this opaque BRDF: 1 - transmission
  // (KHR_materials_transmission's lobe is DielectricBsdf).
  float opaqueWeight = 1.0f;
};

// The dielectric layer's Fresnel at normal and grazing incidence (glTF's
// KHR_materials_specular): f0 = min(f0(ior) * specularColor, 1) * weight,
// f90 = weight.
Spectrum dielectricF0(const BsdfParams& p);

// A BSDF's value and sampling density for one pair of directions, computed
// together: the same bits as eval and pdf called one after the other.
struct BsdfValue {
  Spectrum f{0.0f};  // BSDF value (no cosine)
  float pdf = 0;     // solid angle, of the whole mixture
};

struct BsdfSample {
  Vec3f wi;
  Spectrum f;  // BRDF value (no cosine)
  float pdf;   // solid angle, of the whole mixture
};

class Bsdf {
 public:
  // Smallest GGX alpha: smoother surfaces are treated as this (a near mirror)
  // so that D stays finite in float.
  static constexpr float kMinAlpha = ggx::kMinAlpha;

  explicit Bsdf(const BsdfParams& params);
  // The same BSDF prepared for outgoing directions with wo.z == muO (the
  // renderer's view of a hit, seen from one direction): what depends on wo
  // alone (the specular albedo under the diffuse, Smith's Lambda, the lobe
  // choice) is computed here once instead of in every eval, pdf and sample.
  // Any other wo still works; the values are the same bits either way.
  Bsdf(const BsdfParams& params, float muO);

  Spectrum eval(const Vec3f& wo, const Vec3f& wi) const;
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  // Both at once, sharing the half vector and D.
  BsdfValue evalPdf(const Vec3f& wo, const Vec3f& wi) const;
  // uLobe picks the lobe, u the direction. Empty when the sample falls below
  // the surface or has zero density.
  std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, const Vec2f& u) const;

  float alpha() const { return alpha_; }
  // Probability of sampling the specular lobe for this outgoing direction.
  float specularProbability(const Vec3f& wo) const;

  // Pieces exposed for tests against closed forms.
  float ggxD(const Vec3f& h) const;
  float smithLambda(const Vec3f& w) const;

 private:
  float specularPdf(const Vec3f& wo, const Vec3f& wi) const;
  float specularPdfAt(const Vec3f& wo, float d) const;
  float mixturePdf(const Vec3f& wo, const Vec3f& wi, float specular) const;
  Spectrum evalAt(const Vec3f& wo, const Vec3f& wi, const Vec3f& h, float d) const;
  Spectrum dielectricSpecularAlbedo(float mu) const;
  // The wo-only quantities, from the prepared values when mu is muO.
  Spectrum specularAlbedoAt(float mu) const;
  float lambdaAt(const Vec3f& w) const;
  float computeSpecularProbability(float mu) const;
  BsdfParams p_;
  float alpha_;
  Spectrum f0_;
  Spectrum diffuseNorm_{1.0f};  // 1 / (1 - average specular albedo), per channel
  // Prepared for wo.z == muO_ (NaN: nothing prepared, never equal).
  float muO_;
  Spectrum albedoO_{0.0f};
  float lambdaO_ = 0;
  float specularProbabilityO_ = 0;
};

}  // namespace lensrt
