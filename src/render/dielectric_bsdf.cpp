#include "render/dielectric_bsdf.h"

#include <algorithm>
#include <cmath>

#include "render/ggx.h"

namespace lensrt {
namespace {

Vec3f reflect(const Vec3f& wo, const Vec3f& h) {
  return h * (2 * dot(wo, h)) - wo;
}

// wo refracted through the microfacet h (wo.h > 0) into relative index eta;
// nullopt under total internal reflection.
std::optional<Vec3f> refract(const Vec3f& wo, const Vec3f& h, float eta) {
  const float cosI = dot(wo, h);
  const float sin2T = std::max(0.0f, 1 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1) return std::nullopt;
  const float cosT = std::sqrt(1 - sin2T);
  return normalize(-wo / eta + h * (cosI / eta - cosT));
}

}  // namespace

float fresnelDielectric(float cosI, float eta) {
  cosI = std::clamp(cosI, 0.0f, 1.0f);
  const float sin2T = (1 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1) return 1;
  const float cosT = std::sqrt(1 - sin2T);
  const float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5f * (rs * rs + rp * rp);
}

DielectricBsdf::DielectricBsdf(const DielectricParams& p)
    : p_(p), alpha_(ggx::alphaFromRoughness(p.roughness)) {
  p_.specularWeight = std::clamp(p_.specularWeight, 0.0f, 1.0f);
  if (!(p_.eta > 0) || !std::isfinite(p_.eta)) p_.eta = 1;
  // An index-matched interface does not bend light, and the generalised half
  // vector of refraction degenerates there: the thin form is exact.
  if (std::abs(p_.eta - 1) < 1e-3f) p_.thin = true;
}

float DielectricBsdf::reflectWeight(float cosOH) const {
  return p_.specularWeight * fresnelDielectric(cosOH, p_.eta);
}

float DielectricBsdf::reflectance(const Vec3f& wo) const {
  return reflectWeight(wo.z);
}

Spectrum DielectricBsdf::eval(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z == 0) return Spectrum(0.0f);
  const Spectrum one(1.0f);
  if (wi.z > 0 || p_.thin) {
    // Reflection, or thin-walled transmission as the mirror image of it.
    const Vec3f wr{wi.x, wi.y, std::abs(wi.z)};
    Vec3f h = wo + wr;
    const float hl = length(h);
    if (hl == 0) return Spectrum(0.0f);
    h = h / hl;
    const float f = reflectWeight(dot(wo, h));
    const float micro = ggx::D(alpha_, h) * ggx::G2(alpha_, wo, wr) / (4 * wo.z * wr.z);
    if (wi.z > 0) return min(p_.specularColor * f, one) * micro;
    return p_.tint * ((1 - f) * micro);
  }
  // Refraction (Walter et al. 2007): the generalised half vector.
  const float eta = p_.eta;
  Vec3f h = wo + wi * eta;
  const float hl = length(h);
  if (hl == 0) return Spectrum(0.0f);
  h = h / hl;
  if (h.z < 0) h = -h;
  const float cosO = dot(wo, h), cosI = dot(wi, h);
  if (cosO <= 0 || cosI >= 0) return Spectrum(0.0f);  // a microfacet facing away from one side
  const float f = reflectWeight(cosO);
  const float denom = cosI + cosO / eta;
  const float value = ggx::D(alpha_, h) * ggx::G2(alpha_, wo, -wi) * std::abs(cosI * cosO) /
                      (wo.z * std::abs(wi.z) * denom * denom) / (eta * eta);
  return p_.tint * ((1 - f) * value);
}

float DielectricBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z == 0) return 0;
  if (wi.z > 0 || p_.thin) {
    const Vec3f wr{wi.x, wi.y, std::abs(wi.z)};
    Vec3f h = wo + wr;
    const float hl = length(h);
    if (hl == 0) return 0;
    h = h / hl;
    const float f = reflectWeight(dot(wo, h));
    const float lobe = wi.z > 0 ? f : 1 - f;
    return lobe * ggx::visibleNormalPdf(alpha_, wo, h) / (4 * dot(wo, h));
  }
  const float eta = p_.eta;
  Vec3f h = wo + wi * eta;
  const float hl = length(h);
  if (hl == 0) return 0;
  h = h / hl;
  if (h.z < 0) h = -h;
  const float cosO = dot(wo, h), cosI = dot(wi, h);
  if (cosO <= 0 || cosI >= 0) return 0;
  const float f = reflectWeight(cosO);
  const float denom = cosI + cosO / eta;
  return (1 - f) * ggx::visibleNormalPdf(alpha_, wo, h) * std::abs(cosI) / (denom * denom);
}

std::optional<BsdfSample> DielectricBsdf::sample(const Vec3f& wo, float uLobe, const Vec2f& u) const {
  if (wo.z <= 0) return std::nullopt;
  const Vec3f h = ggx::sampleVisibleNormal(wo, alpha_, u);
  const float cosO = dot(wo, h);
  if (cosO <= 0) return std::nullopt;
  const float f = reflectWeight(cosO);
  Vec3f wi;
  if (uLobe < f) {
    wi = reflect(wo, h);
    if (wi.z <= 0) return std::nullopt;
  } else if (p_.thin) {
    wi = reflect(wo, h);
    if (wi.z <= 0) return std::nullopt;
    wi.z = -wi.z;
  } else {
    const std::optional<Vec3f> t = refract(wo, h, p_.eta);
    if (!t || t->z >= 0) return std::nullopt;
    wi = *t;
  }
  const float density = pdf(wo, wi);
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi), density};
}

}  // namespace lensrt
