#include "render/sheen_bsdf.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/constants.h"
#include "render/ggx.h"
#include "render/lazy_rows.h"

namespace lensrt {
namespace {

float charlieD(float r, const Vec3f& h) {
  const float sin2 = std::max(0.0f, 1 - h.z * h.z);
  const float invR = 1 / r;
  return (2 + invR) * std::pow(sin2, 0.5f * invR) / (2 * kPiF);
}

float visibility(float cosO, float cosI) {
  return 1 / (4 * (cosI + cosO - cosI * cosO));
}

// E(roughness, mu) = int D V cos_i dw_i over the hemisphere for a white lobe,
// on a grid over roughness in [kMinRoughness, 1] (r = roughness^2 changes the
// lobe fastest near 0) and sqrt(mu) in [0, 1] (the albedo rises steeply
// toward grazing), by the midpoint rule. Each roughness row is computed the
// first time a lookup needs it (the whole table costs about 800 M
// instructions, a quarter of a second; a material's sheen roughness uses two
// rows): every row is the same numbers whenever it is built.
class SheenAlbedoTable {
 public:
  static constexpr int kN = 48;
  static const SheenAlbedoTable& get() {
    static const SheenAlbedoTable t;
    return t;
  }
  float at(float roughness, float mu) const {
    constexpr float kMin = SheenBsdf::kMinRoughness;
    const float a = std::clamp((roughness - kMin) / (1 - kMin), 0.0f, 1.0f) * (kN - 1);
    const float m = std::sqrt(std::clamp(mu, 0.0f, 1.0f)) * (kN - 1);
    const int i = std::min(int(a), kN - 2), j = std::min(int(m), kN - 2);
    ensureRows(i);
    return bilerp(e_, i, j, a - float(i), m - float(j));
  }

 private:
  SheenAlbedoTable() = default;
  void ensureRows(int i) const {
    rows_.ensure(i, [this](int row) { buildRow(row); });
  }
  void buildRow(int ir) const {
    constexpr int kTheta = 64, kPhi = 32;
    const float roughness = SheenBsdf::kMinRoughness + (1 - SheenBsdf::kMinRoughness) * float(ir) / (kN - 1);
    const float r = roughness * roughness;
    for (int im = 0; im < kN; ++im) {
      const float x = float(im) / (kN - 1);
      const float mu = std::max(1e-4f, x * x);
      const Vec3f wo{std::sqrt(1 - mu * mu), 0, mu};
      // Midpoint rule in (theta_i, phi_i), phi over [0, pi] by symmetry.
      double sum = 0;
      for (int a = 0; a < kTheta; ++a) {
        const float theta = (a + 0.5f) * (kPiF / 2) / kTheta;
        for (int b = 0; b < kPhi; ++b) {
          const float phi = (b + 0.5f) * kPiF / kPhi;
          const Vec3f wi{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
          const Vec3f h = normalize(wo + wi);
          sum += charlieD(r, h) * visibility(wo.z, wi.z) * wi.z * std::sin(theta);
        }
      }
      sum *= 2 * (kPiF / 2 / kTheta) * (kPiF / kPhi);
      e_[ir][im] = std::min(1.0f, float(sum));
    }
  }
  LazyRows<kN> rows_;
  mutable float e_[kN][kN] = {};
};

}  // namespace

SheenBsdf::SheenBsdf(const Spectrum& color, float roughness)
    : color_(max(color, Spectrum(0.0f))),
      roughness_(std::clamp(roughness, kMinRoughness, 1.0f)),
      r_(roughness_ * roughness_) {}

float SheenBsdf::distribution(const Vec3f& h) const {
  return charlieD(r_, h);
}

Spectrum SheenBsdf::eval(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return Spectrum(0.0f);
  const Vec3f h = normalize(wo + wi);
  return color_ * (charlieD(r_, h) * visibility(wo.z, wi.z));
}

float SheenBsdf::pdf(const Vec3f& wo, const Vec3f& wi) const {
  if (wo.z <= 0 || wi.z <= 0) return 0;
  return wi.z * kInvPiF;
}

std::optional<BsdfSample> SheenBsdf::sample(const Vec3f& wo, const Vec2f& u) const {
  if (wo.z <= 0) return std::nullopt;
  const Vec3f wi = ggx::cosineHemisphere(u);
  const float density = pdf(wo, wi);
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{wi, eval(wo, wi), density};
}

float SheenBsdf::albedo(float mu) const {
  return SheenAlbedoTable::get().at(roughness_, mu);
}

}  // namespace lensrt
