#include "render/clearcoat_bsdf.h"

#include <cmath>

#include "render/ggx.h"

namespace lensrt {
namespace {
constexpr float kF0 = 0.04f;  // ior 1.5
}

ClearcoatBsdf::ClearcoatBsdf(float roughness) : alpha_(ggx::alphaFromRoughness(roughness)) {}

Spectrum ClearcoatBsdf::eval(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return Spectrum(0.0f);
  const Vec3f h = normalize(wo + wi);
  const float f = kF0 + (1 - kF0) * ggx::schlickWeight(dot(wo, h));
  const float v = f * ggx::D(alpha_, h) * ggx::G2(alpha_, wo, wi) / (4 * wo.z * wi.z);
  return Spectrum(v);
}

float ClearcoatBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  const Vec3f h = normalize(wo + wi);
  return ggx::visibleNormalPdf(alpha_, wo, h) / (4 * dot(wo, h));
}

std::optional<BsdfSample> ClearcoatBsdf::sample(const Vec3f& wo, const Vec2f& u) const {
  if (wo.z <= 0) return std::nullopt;
  const Vec3f h = ggx::sampleVisibleNormal(wo, alpha_, u);
  const Vec3f wi = h * (2 * dot(wo, h)) - wo;
  if (wi.z <= 0) return std::nullopt;
  const float density = pdf(wo, wi);
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi), density};
}

float ClearcoatBsdf::albedo(float mu) const {
  return ggx::specularAlbedo(alpha_, mu).with(kF0, 1.0f);
}

}  // namespace lensrt
