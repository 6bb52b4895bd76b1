#include "render/ggx.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/constants.h"
#include "core/sampling.h"
#include "render/lazy_rows.h"

namespace lensrt::ggx {
namespace {

float pow5(float x) {
  const float x2 = x * x;
  return x2 * x2 * x;
}

// E(mu) = f0 * one(mu) + (f90 - f0) * schlick(mu), tabulated over (alpha, mu)
// by stratified visible-normal sampling (each sample's weight is G2 / G1),
// with the cosine-weighted averages 2 int E(mu) mu dmu. Each alpha row is
// computed the first time a lookup needs it (a scene's materials use a few
// roughnesses, and the whole table costs about 150 M instructions, most of a
// small render's start): every row is the same numbers whenever it is built.
class AlbedoTable {
 public:
  static constexpr int kN = 32;
  static const AlbedoTable& get() {
    static const AlbedoTable t;
    return t;
  }
  AlbedoTerms at(float alpha, float mu) const {
    const float a = std::clamp(alpha, 0.0f, 1.0f) * (kN - 1), m = std::clamp(mu, 0.0f, 1.0f) * (kN - 1);
    const int i = std::min(int(a), kN - 2), j = std::min(int(m), kN - 2);
    ensureRows(i);
    const float s = a - float(i), t = m - float(j);
    return {bilerp(one_, i, j, s, t), bilerp(schlick_, i, j, s, t)};
  }
  AlbedoTerms average(float alpha) const {
    const float a = std::clamp(alpha, 0.0f, 1.0f) * (kN - 1);
    const int i = std::min(int(a), kN - 2);
    ensureRows(i);
    const float t = a - float(i);
    return {avgOne_[i] * (1 - t) + avgOne_[i + 1] * t, avgSchlick_[i] * (1 - t) + avgSchlick_[i + 1] * t};
  }

 private:
  AlbedoTable() = default;
  void ensureRows(int i) const {
    rows_.ensure(i, [this](int row) { buildRow(row); });
  }
  void buildRow(int ia) const {
    constexpr int kStrata = 24;
    const float alpha = std::max(kMinAlpha, float(ia) / (kN - 1));
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
          const float lo = lambda(alpha, wo), li = lambda(alpha, wi);
          const double w = (1 + lo) / (1 + lo + li);  // G2 / G1
          one += w;
          schlick += w * pow5(std::clamp(1 - dot(wo, h), 0.0f, 1.0f));
        }
      one_[ia][im] = float(one / (kStrata * kStrata));
      schlick_[ia][im] = float(schlick / (kStrata * kStrata));
      const float w = (im == 0 || im == kN - 1) ? 0.5f : 1.0f;  // trapezoid rule
      sumOne += w * one_[ia][im] * mu;
      sumSchlick += w * schlick_[ia][im] * mu;
    }
    avgOne_[ia] = float(2 * sumOne / (kN - 1));
    avgSchlick_[ia] = float(2 * sumSchlick / (kN - 1));
  }
  LazyRows<kN> rows_;
  mutable float one_[kN][kN] = {};
  mutable float schlick_[kN][kN] = {};
  mutable float avgOne_[kN] = {};
  mutable float avgSchlick_[kN] = {};
};

}  // namespace

float alphaFromRoughness(float roughness) {
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  return std::max(kMinAlpha, r * r);
}

float D(float alpha, const Vec3f& h) {
  if (h.z <= 0) return 0;
  const float a2 = alpha * alpha;
  const float d = h.z * h.z * (a2 - 1) + 1;
  return a2 / (kPiF * d * d);
}

float lambda(float alpha, const Vec3f& w) {
  const float cos2 = w.z * w.z;
  if (cos2 <= 0) return kInfinityF;
  const float tan2 = std::max(0.0f, 1 - cos2) / cos2;
  return 0.5f * (std::sqrt(1 + alpha * alpha * tan2) - 1);
}

float visibleNormalPdf(float alpha, const Vec3f& wo, const Vec3f& h) {
  if (wo.z <= 0) return 0;
  return G1(alpha, wo) * D(alpha, h) * std::max(0.0f, dot(wo, h)) / wo.z;
}

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

float schlickWeight(float cosTheta) {
  return pow5(std::clamp(1.0f - cosTheta, 0.0f, 1.0f));
}

Vec3f cosineHemisphere(const Vec2f& u) {
  const Vec2f d = concentricDisk(u);  // Malley: project the disk up
  return {d.x, d.y, std::sqrt(std::max(0.0f, 1 - d.x * d.x - d.y * d.y))};
}

AlbedoTerms specularAlbedo(float alpha, float mu) {
  return AlbedoTable::get().at(alpha, mu);
}
AlbedoTerms averageSpecularAlbedo(float alpha) {
  return AlbedoTable::get().average(alpha);
}

}  // namespace lensrt::ggx
