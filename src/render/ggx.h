// The GGX (Trowbridge-Reitz) microfacet model shared by the glTF BSDF's
// lobes: normal distribution, height-correlated Smith masking, sampling of
// visible normals (Heitz 2018), and the directional albedo of a GGX
// reflection lobe with Schlick Fresnel, tabulated once.
// Directions are in a local frame (z = the lobe's normal), unit length.
#pragma once

#include "core/vec.h"
#include "render/spectrum.h"

namespace lensrt::ggx {

// Smallest alpha: smoother surfaces are treated as this (a near mirror) so
// that D stays finite in float.
inline constexpr float kMinAlpha = 1e-3f;

// alpha = perceptual roughness^2, clamped to [kMinAlpha, 1].
float alphaFromRoughness(float roughness);

float D(float alpha, const Vec3f& h);  // zero for h below the surface
float lambda(float alpha, const Vec3f& w);
inline float G1(float alpha, const Vec3f& w) {
  return 1.0f / (1.0f + lambda(alpha, w));
}
inline float G2(float alpha, const Vec3f& wo, const Vec3f& wi) {
  return 1.0f / (1.0f + lambda(alpha, wo) + lambda(alpha, wi));
}
// Density of visible normals seen from wo (wo.z > 0): G1(wo) D(h) max(0, wo.h) / wo.z.
float visibleNormalPdf(float alpha, const Vec3f& wo, const Vec3f& h);
// A visible normal of the surface seen from wo (wo.z > 0).
Vec3f sampleVisibleNormal(const Vec3f& wo, float alpha, const Vec2f& u);

// (1 - cos)^5, the Schlick Fresnel weight.
float schlickWeight(float cosTheta);
// Cosine-weighted hemisphere (concentric mapping, keeps stratification).
Vec3f cosineHemisphere(const Vec2f& u);

// Directional albedo of a GGX reflection lobe whose Fresnel is
// f0 + (f90 - f0) (1 - v.h)^5, as the two terms {one, schlick} with
// E = f0 * one + (f90 - f0) * schlick, at (alpha, mu = cos theta_o), and their
// cosine-weighted hemispherical averages at alpha.
struct AlbedoTerms {
  float one = 0, schlick = 0;
  float with(float f0, float f90) const { return f0 * one + (f90 - f0) * schlick; }
  Spectrum with(const Spectrum& f0, float f90) const {
    return {with(f0[0], f90), with(f0[1], f90), with(f0[2], f90), with(f0[3], f90)};
  }
};
AlbedoTerms specularAlbedo(float alpha, float mu);
AlbedoTerms averageSpecularAlbedo(float alpha);

}  // namespace lensrt::ggx
