// KHR_materials_sheen's lobe: the "Charlie" distribution of Estevez and Kulla
// (Imageworks 2017), D(h) = (2 + 1/r) sin(theta_h)^(1/r) / (2 pi) with
// r = sheenRoughness^2, and Ashikhmin's visibility 1 / (4 (cos_i + cos_o -
// cos_i cos_o)), which keeps the lobe reciprocal. Sampled by the cosine
// (the lobe is broad). Its directional albedo is tabulated once; the layer
// under the sheen is scaled by 1 - max(sheenColor) E (see gltf_bsdf.h).
// Local frame: z = shading normal, both directions above it.
#pragma once

#include <optional>

#include "core/vec.h"
#include "render/bsdf.h"
#include "render/spectrum.h"

namespace lensrt {

class SheenBsdf {
 public:
  // Smallest r: below it the distribution is a spike at grazing that the
  // albedo table cannot follow.
  static constexpr float kMinRoughness = 0.1f;  // r = 0.01

  SheenBsdf(const Spectrum& color, float roughness);

  Spectrum eval(const Vec3f& wo, const Vec3f& wi) const;
  float pdf(const Vec3f& wo, const Vec3f& wi) const;
  std::optional<BsdfSample> sample(const Vec3f& wo, const Vec2f& u) const;
  // Directional albedo of the lobe with a white sheen colour at cos theta = mu.
  float albedo(float mu) const;

  float distribution(const Vec3f& h) const;  // D(h), for tests

 private:
  Spectrum color_;
  float roughness_;  // clamped to [kMinRoughness, 1]
  float r_;
};

}  // namespace lensrt
