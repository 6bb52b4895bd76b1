#include "render/bsdf.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/constants.h"

namespace lensrt {

// The diffuse term is scaled by (1 - E(mu_o)) (1 - E(mu_i)) / (1 - E_avg), E
// the specular layer's directional albedo (Kelemen and Szirmay-Kalos 2001):
// reciprocal, and the total albedo is exactly E + rho (1 - E) <= 1. glTF's own
// mix with F(v.h) is not energy conserving at grazing angles (albedo up to ~1.3).

Spectrum dielectricF0(const BsdfParams& p) {
  const float ior = std::max(1.0f, p.ior);
  const float r = (ior - 1) / (ior + 1);
  const float w = std::clamp(p.specularWeight, 0.0f, 1.0f);
  const Spectrum one(1.0f);
  return min(p.specularColor * (r * r), one) * w;
}

Spectrum Bsdf::dielectricSpecularAlbedo(float mu) const {
  return ggx::specularAlbedo(alpha_, mu).with(f0_, p_.specularWeight);
}

Bsdf::Bsdf(const BsdfParams& params) : Bsdf(params, std::numeric_limits<float>::quiet_NaN()) {}

Bsdf::Bsdf(const BsdfParams& params, float muO)
    : p_(params), alpha_(ggx::alphaFromRoughness(params.roughness)), f0_(dielectricF0(params)), muO_(muO) {
  p_.metallic = std::clamp(p_.metallic, 0.0f, 1.0f);
  p_.opaqueWeight = std::clamp(p_.opaqueWeight, 0.0f, 1.0f);
  p_.specularWeight = std::clamp(p_.specularWeight, 0.0f, 1.0f);
  const Spectrum average = ggx::averageSpecularAlbedo(alpha_).with(f0_, p_.specularWeight);
  for (std::size_t c = 0; c < Spectrum::kLanes; ++c) diffuseNorm_[c] = 1.0f / std::max(1e-4f, 1 - average[c]);
  if (muO_ == muO_) {  // not NaN
    albedoO_ = p_.specularWeight > 0 ? dielectricSpecularAlbedo(muO_) : Spectrum(0.0f);
    lambdaO_ = ggx::lambda(alpha_, Vec3f{0, 0, muO_});
    specularProbabilityO_ = computeSpecularProbability(muO_);
  }
}

// Without a specular layer (KHR_materials_specular 0) f0 and f90 are 0 and
// so is the albedo, whatever the table says.
Spectrum Bsdf::specularAlbedoAt(float mu) const {
  if (mu == muO_) return albedoO_;
  return p_.specularWeight > 0 ? dielectricSpecularAlbedo(mu) : Spectrum(0.0f);
}

// Lambda depends on the cosine alone.
float Bsdf::lambdaAt(const Vec3f& w) const {
  return w.z == muO_ ? lambdaO_ : ggx::lambda(alpha_, w);
}

float Bsdf::ggxD(const Vec3f& h) const {
  return ggx::D(alpha_, h);
}

float Bsdf::smithLambda(const Vec3f& w) const {
  return ggx::lambda(alpha_, w);
}

Spectrum Bsdf::eval(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return Spectrum(0.0f);
  Vec3f h = wo + wi;
  const float hl = length(h);
  if (hl == 0) return Spectrum(0.0f);
  h = h / hl;
  return evalAt(wo, wi, h, ggxD(h));
}

// eval for the unit half vector h of wo and wi and d = D(h).
Spectrum Bsdf::evalAt(const Vec3f& wo, const Vec3f& wi, const Vec3f& h, float d) const {
  const float vDotH = std::max(0.0f, dot(wo, h));
  const float fw = ggx::schlickWeight(vDotH);
  // Height-correlated Smith G2 over the usual 4 cos cos denominator.
  const float g2 = 1.0f / (1.0f + lambdaAt(wo) + lambdaAt(wi));
  const float spec = d * g2 / (4 * wo.z * wi.z);
  const Spectrum one(1.0f);
  const Spectrum fDielectric = f0_ + (one * p_.specularWeight - f0_) * fw;
  const Spectrum fMetal = p_.baseColor + (one - p_.baseColor) * fw;
  Spectrum diffuse = one;
  if (p_.specularWeight > 0)
    diffuse = (one - specularAlbedoAt(wo.z)) * (one - specularAlbedoAt(wi.z)) * diffuseNorm_;
  const Spectrum dielectric = p_.baseColor * diffuse * kInvPiF + fDielectric * spec;
  return dielectric * ((1 - p_.metallic) * p_.opaqueWeight) + fMetal * (spec * p_.metallic);
}

float Bsdf::specularProbability(const Vec3f& wo) const {
  return wo.z == muO_ ? specularProbabilityO_ : computeSpecularProbability(wo.z);
}

float Bsdf::computeSpecularProbability(float mu) const {
  // Lobe weights from the Fresnel at normal-ish incidence estimated with wo.z.
  const float fw = ggx::schlickWeight(std::max(0.0f, mu));
  const Spectrum one(1.0f);
  const float fd = luminance(f0_ + (one * p_.specularWeight - f0_) * fw);
  const float dielectric = (1 - p_.metallic) * p_.opaqueWeight;
  const float spec = dielectric * fd + p_.metallic * luminance(p_.baseColor + (one - p_.baseColor) * fw);
  const float diffuse = dielectric * luminance((one - specularAlbedoAt(mu)) * p_.baseColor);
  if (spec + diffuse <= 0) return 0.5f;
  return spec / (spec + diffuse);
}

float Bsdf::specularPdf(const Vec3f& wo, const Vec3f& wi) const {
  Vec3f h = wo + wi;
  const float hl = length(h);
  if (hl == 0) return 0;
  h = h / hl;
  return specularPdfAt(wo, ggxD(h));
}

// Visible-normal pdf times the reflection Jacobian 1 / (4 wo.h), for d = D(h).
float Bsdf::specularPdfAt(const Vec3f& wo, float d) const {
  const float g1 = 1.0f / (1.0f + lambdaAt(wo));
  return g1 * d / (4 * wo.z);
}

float Bsdf::mixturePdf(const Vec3f& wo, const Vec3f& wi, float specular) const {
  const float ps = specularProbability(wo);
  return ps * specular + (1 - ps) * wi.z * kInvPiF;
}

float Bsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  return mixturePdf(wo, wi, specularPdf(wo, wi));
}

BsdfValue Bsdf::evalPdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {};
  Vec3f h = wo + wi;
  const float hl = length(h);
  if (hl == 0) return {Spectrum(0.0f), mixturePdf(wo, wi, 0)};
  h = h / hl;
  const float d = ggxD(h);
  return {evalAt(wo, wi, h, d), mixturePdf(wo, wi, specularPdfAt(wo, d))};
}

std::optional<BsdfSample> Bsdf::sample(const Vec3f& wo, float uLobe, const Vec2f& u) const {
  if (wo.z <= 0) return std::nullopt;
  Vec3f wi;
  if (uLobe < specularProbability(wo)) {
    const Vec3f h = ggx::sampleVisibleNormal(wo, alpha_, u);
    wi = h * (2 * dot(wo, h)) - wo;
  } else {
    wi = ggx::cosineHemisphere(u);
  }
  if (wi.z <= 0) return std::nullopt;
  const BsdfValue v = evalPdf(wo, wi);
  if (!(v.pdf > 0)) return std::nullopt;
  return BsdfSample{wi, v.f, v.pdf};
}

}  // namespace lensrt
