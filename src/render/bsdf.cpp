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
float schlickWeight(float cosTheta) {
  return pow5(std::clamp(1.0f - cosTheta, 0.0f, 1.0f));
}

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

// Heitz 2018: a visible normal of the GGX surface (alpha) seen from wo.
Vec3f sampleVisibleNormal(const Vec3f& wo, float alpha, const Vec2f& u) {
  const Vec3f vh = normalize(Vec3f{alpha * wo.x, alpha * wo.y, wo.z});
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec3f t1 = lensq > 0 ? Vec3f{-vh.y, vh.x, 0} / std::sqrt(lensq) : Vec3f{1, 0, 0};
  const Vec3f t2 = cross(vh, t1);
  const float r = std::sqrt(u.x), phi = 2 * kPiF * u.y;
  const float p1 = r * std::cos(phi);
  float p2 = r * std::sin(phi);
  const float s = 0.5f * (1 + vh.z);
  p2 = (1 - s) * std::sqrt(std::max(0.0f, 1 - p1 * p1)) + s * p2;
  const Vec3f nh = t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(0.0f, 1 - p1 * p1 - p2 * p2));
  return normalize(Vec3f{alpha * nh.x, alpha * nh.y, std::max(1e-6f, nh.z)});
}

float smithLambdaFor(float alpha, const Vec3f& w) {
  const float cos2 = w.z * w.z;
  if (cos2 <= 0) return kInfinityF;
  const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
  return 0.5f * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}

// Directional albedo of the specular layer, E(mu) = f0 * one(mu) + (1 - f0) *
// schlick(mu), tabulated over (alpha, mu) once (by stratified visible-normal
// sampling, where each sample's weight is F G2 / G1), plus its cosine-weighted
// hemispherical averages. The diffuse term is scaled by (1 - E(mu_o)) (1 -
// E(mu_i)) / (1 - E_avg) (Kelemen and Szirmay-Kalos 2001): reciprocal, and the
// total albedo is exactly E + rho (1 - E) <= 1. glTF's own mix with F(v.h) is
// not energy conserving at grazing angles (albedo up to ~1.3).
class SpecularAlbedo {
 public:
  static constexpr int kN = 32;
  static const SpecularAlbedo& table() {
    static const SpecularAlbedo t;
    return t;
  }
  // {one, schlick} terms at (alpha, mu) and their averages at alpha.
  void lookup(float alpha, float mu, float* one, float* schlick) const {
    interpolate(alpha, mu, one, schlick);
  }
  void average(float alpha, float* one, float* schlick) const {
    const float a = std::clamp(alpha, 0.0f, 1.0f) * (kN - 1);
    const int i = std::min(int(a), kN - 2);
    const float t = a - float(i);
    *one = avgOne_[i] * (1 - t) + avgOne_[i + 1] * t;
    *schlick = avgSchlick_[i] * (1 - t) + avgSchlick_[i + 1] * t;
  }

 private:
  SpecularAlbedo() {
    constexpr int kStrata = 24;
    for (int ia = 0; ia < kN; ++ia) {
      const float alpha = std::max(Bsdf::kMinAlpha, float(ia) / (kN - 1));
      double sumOne = 0, sumSchlick = 0;
      for (int im = 0; im < kN; ++im) {
        const float mu = std::max(1e-3f, float(im) / (kN - 1));
        const Vec3f wo{std::sqrt(1 - mu * mu), 0, mu};
        double one = 0, schlick = 0;
        for (int a = 0; a < kStrata; ++a)
          for (int b = 0; b < kStrata; ++b) {
            const Vec3f h = sampleVisibleNormal(wo, alpha, {(a + 0.5f) / kStrata, (b + 0.5f) / kStrata});
            const Vec3f wi = h * (2 * dot(wo, h)) - wo;
            if (wi.z <= 0) continue;
            const float lo = smithLambdaFor(alpha, wo), li = smithLambdaFor(alpha, wi);
            const double w = (1 + lo) / (1 + lo + li);  // G2 / G1
            one += w;
            schlick += w * pow5(std::clamp(1 - dot(wo, h), 0.0f, 1.0f));
          }
        one_[ia][im] = float(one / (kStrata * kStrata));
        schlick_[ia][im] = float(schlick / (kStrata * kStrata));
        // Average 2 int E(mu) mu dmu by the trapezoid rule.
        const float w = (im == 0 || im == kN - 1) ? 0.5f : 1.0f;
        sumOne += w * one_[ia][im] * mu;
        sumSchlick += w * schlick_[ia][im] * mu;
      }
      avgOne_[ia] = float(2 * sumOne / (kN - 1));
      avgSchlick_[ia] = float(2 * sumSchlick / (kN - 1));
    }
  }
  void interpolate(float alpha, float mu, float* one, float* schlick) const {
    const float a = std::clamp(alpha, 0.0f, 1.0f) * (kN - 1), m = std::clamp(mu, 0.0f, 1.0f) * (kN - 1);
    const int i = std::min(int(a), kN - 2), j = std::min(int(m), kN - 2);
    const float s = a - float(i), t = m - float(j);
    const auto bilerp = [&](const float(&v)[kN][kN]) {
      return (v[i][j] * (1 - t) + v[i][j + 1] * t) * (1 - s) +
             (v[i + 1][j] * (1 - t) + v[i + 1][j + 1] * t) * s;
    };
    *one = bilerp(one_);
    *schlick = bilerp(schlick_);
  }
  float one_[kN][kN];
  float schlick_[kN][kN];
  float avgOne_[kN];
  float avgSchlick_[kN];
};

}  // namespace

float Bsdf::dielectricSpecularAlbedo(float mu) const {
  float one = 0, schlick = 0;
  SpecularAlbedo::table().lookup(alpha_, mu, &one, &schlick);
  return p_.specularWeight * (0.04f * one + 0.96f * schlick);
}

Bsdf::Bsdf(const BsdfParams& params)
    : p_(params),
      alpha_(std::max(kMinAlpha,
                      std::clamp(params.roughness, 0.0f, 1.0f) * std::clamp(params.roughness, 0.0f, 1.0f))) {
  p_.metallic = std::clamp(p_.metallic, 0.0f, 1.0f);
  p_.specularWeight = std::clamp(p_.specularWeight, 0.0f, 1.0f);
  float one = 0, schlick = 0;
  SpecularAlbedo::table().average(alpha_, &one, &schlick);
  const float average = p_.specularWeight * (0.04f * one + 0.96f * schlick);
  diffuseNorm_ = 1.0f / std::max(1e-4f, 1 - average);
}

float Bsdf::ggxD(const Vec3f& h) const {
  if (h.z <= 0) return 0;
  const float a2 = alpha_ * alpha_;
  const float d = h.z * h.z * (a2 - 1) + 1;
  return a2 / (kPiF * d * d);
}

float Bsdf::smithLambda(const Vec3f& w) const {
  return smithLambdaFor(alpha_, w);
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
  const float diffuse = p_.specularWeight > 0 ? (1 - dielectricSpecularAlbedo(wo.z)) *
                                                    (1 - dielectricSpecularAlbedo(wi.z)) * diffuseNorm_
                                              : 1.0f;
  const Rgb dielectric = p_.baseColor * (diffuse * kInvPiF) + one * (fDielectric * spec);
  return dielectric * (1 - p_.metallic) + fMetal * (spec * p_.metallic);
}

float Bsdf::specularProbability(const Vec3f& wo) const {
  // Lobe weights from the Fresnel at normal-ish incidence estimated with wo.z.
  const float fw = schlickWeight(std::max(0.0f, wo.z));
  const float fd = p_.specularWeight * (0.04f + 0.96f * fw);
  const Rgb one{1, 1, 1};
  const float spec =
      (1 - p_.metallic) * fd + p_.metallic * luminance(p_.baseColor + (one - p_.baseColor) * fw);
  const float diffuse = (1 - p_.metallic) * (1 - dielectricSpecularAlbedo(wo.z)) * luminance(p_.baseColor);
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
    const Vec3f h = sampleVisibleNormal(wo, alpha_, u);
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
