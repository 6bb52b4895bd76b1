#include "render/bsdf.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace lensrt {
namespace {

float pow5(float x) {
  const float x2 = x * x;
  return x2 * x2 * x;
}
float schlickWeight(float cosTheta) { return pow5(std::clamp(1.0f - cosTheta, 0.0f, 1.0f)); }

Vec3f cosineHemisphere(const Vec2f& u) {
  // Concentric disk mapping (Shirley-Chiu) lifted to the hemisphere: keeps the
  // sampler's stratification.
  const float a = 2 * u.x - 1, b = 2 * u.y - 1;
  float r = 0, phi = 0;
  if (a != 0 || b != 0) {
    if (std::abs(a) > std::abs(b)) {
      r = a;
      phi = (kPiF / 4) * (b / a);
    } else {
      r = b;
      phi = kPiF / 2 - (kPiF / 4) * (a / b);
    }
  }
  const float x = r * std::cos(phi), y = r * std::sin(phi);
  return {x, y, std::sqrt(std::max(0.0f, 1 - x * x - y * y))};
}

}  // namespace

Bsdf::Bsdf(const BsdfParams& params)
    : p_(params),
      alpha_(std::max(kMinAlpha, std::clamp(params.roughness, 0.0f, 1.0f) * std::clamp(params.roughness, 0.0f, 1.0f))) {
  p_.metallic = std::clamp(p_.metallic, 0.0f, 1.0f);
  p_.specularWeight = std::clamp(p_.specularWeight, 0.0f, 1.0f);
}

float Bsdf::ggxD(const Vec3f& h) const {
  if (h.z <= 0) return 0;
  const float a2 = alpha_ * alpha_;
  const float d = h.z * h.z * (a2 - 1) + 1;
  return a2 / (kPiF * d * d);
}

float Bsdf::smithLambda(const Vec3f& w) const {
  const float cos2 = w.z * w.z;
  if (cos2 <= 0) return kInfinityF;
  const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
  return 0.5f * (std::sqrt(1 + alpha_ * alpha_ * tan2) - 1);
}

Rgb Bsdf::eval(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return {0, 0, 0};
  Vec3f h = wo + wi;
  const float hl = length(h);
  if (hl == 0) return {0, 0, 0};
  h = h / hl;
  const float vDotH = std::max(0.0f, dot(wo, h));
  const float fw = schlickWeight(vDotH);
  // Height-correlated Smith G2 over the usual 4 cos cos denominator.
  const float g2 = 1.0f / (1.0f + smithLambda(wo) + smithLambda(wi));
  const float spec = ggxD(h) * g2 / (4 * wo.z * wi.z);
  const float fDielectric = p_.specularWeight * (0.04f + 0.96f * fw);
  const Rgb one{1, 1, 1};
  const Rgb fMetal = p_.baseColor + (one - p_.baseColor) * fw;
  const Rgb dielectric = p_.baseColor * ((1 - fDielectric) * kInvPiF) + one * (fDielectric * spec);
  return dielectric * (1 - p_.metallic) + fMetal * (spec * p_.metallic);
}

float Bsdf::specularProbability(const Vec3f& wo) const {
  // Lobe weights from the Fresnel at normal-ish incidence estimated with wo.z.
  const float fw = schlickWeight(std::max(0.0f, wo.z));
  const float fd = p_.specularWeight * (0.04f + 0.96f * fw);
  const Rgb one{1, 1, 1};
  const float spec = (1 - p_.metallic) * fd + p_.metallic * luminance(p_.baseColor + (one - p_.baseColor) * fw);
  const float diffuse = (1 - p_.metallic) * (1 - fd) * luminance(p_.baseColor);
  if (spec + diffuse <= 0) return 0.5f;
  return spec / (spec + diffuse);
}

float Bsdf::specularPdf(const Vec3f& wo, const Vec3f& wi) const {
  Vec3f h = wo + wi;
  const float hl = length(h);
  if (hl == 0) return 0;
  h = h / hl;
  // Visible-normal pdf G1(wo) D(h) max(0, wo.h) / wo.z, times the reflection
  // Jacobian 1 / (4 wo.h).
  const float g1 = 1.0f / (1.0f + smithLambda(wo));
  return g1 * ggxD(h) / (4 * wo.z);
}

float Bsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  const float ps = specularProbability(wo);
  return ps * specularPdf(wo, wi) + (1 - ps) * wi.z * kInvPiF;
}

std::optional<BsdfSample> Bsdf::sample(const Vec3f& wo, float uLobe, const Vec2f& u) const {
  if (wo.z <= 0) return std::nullopt;
  Vec3f wi;
  if (uLobe < specularProbability(wo)) {
    // Heitz 2018: sample the visible normals of the stretched hemisphere.
    const Vec3f vh = normalize(Vec3f{alpha_ * wo.x, alpha_ * wo.y, wo.z});
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3f t1 = lensq > 0 ? Vec3f{-vh.y, vh.x, 0} / std::sqrt(lensq) : Vec3f{1, 0, 0};
    const Vec3f t2 = cross(vh, t1);
    const float r = std::sqrt(u.x), phi = 2 * kPiF * u.y;
    const float p1 = r * std::cos(phi);
    float p2 = r * std::sin(phi);
    const float s = 0.5f * (1 + vh.z);
    p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * p2;
    const Vec3f nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2));
    const Vec3f h = normalize(Vec3f{alpha_ * nh.x, alpha_ * nh.y, std::max(1e-6f, nh.z)});
    wi = h * (2 * dot(wo, h)) - wo;
  } else {
    wi = cosineHemisphere(u);
  }
  if (wi.z <= 0) return std::nullopt;
  const float density = pdf(wo, wi);
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi), density};
}

}  // namespace lensrt
