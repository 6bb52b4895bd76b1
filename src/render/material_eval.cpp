#include "render/material_eval.h"

#include <algorithm>
#include <cmath>

#include "scene/texture_sampling.h"

namespace lensrt {

MaterialTable::MaterialTable(const SceneDesc& scene) : scene_(&scene), extras_(scene.materials.size() + 1) {
  default_.name = "glTF default";
}

const Material& MaterialTable::material(int index) const {
  return index >= 0 && std::size_t(index) < scene_->materials.size() ? scene_->materials[index] : default_;
}
const MaterialTable::Extra& MaterialTable::extra(int index) const {
  return index >= 0 && std::size_t(index) < scene_->materials.size() ? extras_[index + 1] : extras_[0];
}
MaterialTable::Extra& MaterialTable::extra(int index) {
  return index >= 0 && std::size_t(index) < scene_->materials.size() ? extras_[index + 1] : extras_[0];
}

namespace {

// A texture slot at a point with UV sets uv0 (TEXCOORD_0) and uv1 (TEXCOORD_1):
// the slot picks its set and applies its KHR_texture_transform.
Vec4f lookup(const SceneDesc& scene, const TextureRef& ref, const Vec2f& uv0, const Vec2f& uv1) {
  if (!ref.valid() || std::size_t(ref.texture) >= scene.textures.size()) return {1, 1, 1, 1};
  return sampleTexture(scene.textures[ref.texture], ref.uv(uv0, uv1));
}
Vec4f lookup(const SceneDesc& scene, const TextureRef& ref, const SurfaceHit& hit) {
  return lookup(scene, ref, hit.uv, hit.uv1);
}

// World-space tangent (xyz = dp/du, w = handedness) of the hit triangle from
// its uv parameterisation, for meshes that come without TANGENT: a per-face
// stand-in for MikkTSpace. glTF's v runs down the image while normal maps
// point +Y up, so the bitangent is -dp/dv. Zero when the uvs are degenerate.
// The uvs are those the normal texture reads: its UV set through its
// KHR_texture_transform, so a rotated or mirrored map turns its frame too.
Vec4f faceTangent(const SceneDesc& scene, const SurfaceHit& hit, const TextureRef& ref) {
  if (hit.instance < 0 || std::size_t(hit.instance) >= scene.instances.size()) return {};
  const MeshInstance& inst = scene.instances[hit.instance];
  const Mesh& mesh = scene.meshes[inst.mesh];
  const std::vector<Vec2f>& uvs = ref.texCoord == 1 ? mesh.uvs1 : mesh.uvs;
  if (uvs.empty() || 3 * std::size_t(hit.primitive) + 2 >= mesh.indices.size()) return {};
  const std::uint32_t* idx = &mesh.indices[3 * std::size_t(hit.primitive)];
  const Vec3f p0 = inst.worldFromObject.point(mesh.positions[idx[0]]);
  const Vec3f e1 = inst.worldFromObject.point(mesh.positions[idx[1]]) - p0;
  const Vec3f e2 = inst.worldFromObject.point(mesh.positions[idx[2]]) - p0;
  const Vec2f t0 = ref.transform.apply(uvs[idx[0]]);
  const Vec2f d1 = ref.transform.apply(uvs[idx[1]]) - t0, d2 = ref.transform.apply(uvs[idx[2]]) - t0;
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (!(std::abs(det) > 1e-12f)) return {};
  const Vec3f dpdu = (e1 * d2.y - e2 * d1.y) / det;
  const Vec3f dpdv = (e2 * d1.x - e1 * d2.x) / det;
  if (!(lengthSquared(dpdu) > 0) || !isFinite(dpdu)) return {};
  const Vec3f t = normalize(dpdu);
  const float w = dot(cross(hit.shadingNormal, t), -dpdv) < 0 ? -1.0f : 1.0f;
  return {t.x, t.y, t.z, w};
}

}  // namespace

Rgb emittedRadiance(const MaterialTable& materials, int index, const Vec2f& uv0, const Vec2f& uv1,
                    float cosFront) {
  const Material& m = materials.material(index);
  if (!m.isEmissive()) return {0, 0, 0};
  if (!m.doubleSided && cosFront <= 0) return {0, 0, 0};
  return m.emissive * lookup(materials.scene(), m.emissiveTexture, uv0, uv1).xyz();
}

namespace {

// A vertex TANGENT frame turned by the slot's KHR_texture_transform, as
// faceTangent's frame from the uvs turns: the map's +u' on the surface is
// dp/du' = (A^-1)_00 dp/du + (A^-1)_10 dp/dv for the transform's linear part
// A, with dp/du along the tangent and dp/dv against the bitangent, of the
// same length (the conformal parameterisation one tangent per vertex
// implies). A mirror flips the handedness. The identity leaves it as it is.
Vec4f transformedTangent(const Vec4f& tangent, const Vec3f& normal, const UvTransform& x) {
  const float a = x.m[0], b = x.m[1], c = x.m[3], d = x.m[4];
  if (a == 1 && b == 0 && c == 0 && d == 1) return tangent;
  const float det = a * d - b * c;
  if (!(std::abs(det) > 1e-12f)) return tangent;
  const Vec3f dpdu = tangent.xyz();
  const Vec3f dpdv = -cross(normal, dpdu) * (tangent.w < 0 ? -1.0f : 1.0f);
  const Vec3f dpdu2 = (dpdu * d - dpdv * c) / det, dpdv2 = (dpdv * a - dpdu * b) / det;
  if (!(lengthSquared(dpdu2) > 0) || !isFinite(dpdu2)) return tangent;
  const Vec3f t = normalize(dpdu2);
  const float w = dot(cross(normal, t), -dpdv2) < 0 ? -1.0f : 1.0f;
  return {t.x, t.y, t.z, w};
}

// The normal n (unit, facing the viewer) perturbed by a tangent-space normal
// map, or n itself when the slot or the tangent frame is missing.
Vec3f mapNormal(const SceneDesc& scene, const SurfaceHit& hit, const TextureRef& ref, float scale, Vec3f n) {
  if (!ref.valid()) return n;
  const bool hasTangent = hit.tangent.x != 0 || hit.tangent.y != 0 || hit.tangent.z != 0;
  const Vec4f tangent4 = hasTangent ? transformedTangent(hit.tangent, hit.shadingNormal, ref.transform)
                                    : faceTangent(scene, hit, ref);
  if (tangent4.x == 0 && tangent4.y == 0 && tangent4.z == 0) return n;
  const Vec4f t = lookup(scene, ref, hit);
  const Vec3f local{(2 * t.x - 1) * scale, (2 * t.y - 1) * scale, 2 * t.z - 1};
  // Gram-Schmidt the interpolated tangent against the shading normal.
  const Vec3f tangent0 = tangent4.xyz();
  Vec3f tangent = tangent0 - n * dot(n, tangent0);
  if (!(lengthSquared(tangent) > 1e-12f)) return n;
  tangent = normalize(tangent);
  const Vec3f bitangent = cross(n, tangent) * (tangent4.w < 0 ? -1.0f : 1.0f);
  const Vec3f mapped = tangent * local.x + bitangent * local.y + n * local.z;
  if (lengthSquared(mapped) > 0 && isFinite(mapped)) return normalize(mapped);
  return n;
}

// A shading normal facing away from the viewer would make the BSDF zero for
// every light: fall back to the geometric normal there.
Frame viewerFrame(Vec3f n, const Vec3f& wo, const Vec3f& geometricNormal) {
  if (dot(n, wo) <= 1e-4f) n = geometricNormal;
  return Frame::fromNormal(n);
}

Rgb rgb(const Vec4f& v) {
  return {v.x, v.y, v.z};
}

}  // namespace

bool isDispersiveVolume(const Material& m) {
  return m.dispersion > 0 && m.transmission > 0 && !m.thinWalled();
}

ShadingPoint evaluateMaterial(const MaterialTable& materials, const SurfaceHit& hit, const Vec3f& wo,
                              const SampledWavelengths& lambda) {
  const SceneDesc& scene = materials.scene();
  const Material& m = materials.material(hit.material);
  ShadingPoint sp;

  // Shade whichever side the viewer is on.
  const bool back = dot(wo, hit.geometricNormal) < 0;
  sp.frontFace = !back;
  sp.geometricNormal = back ? -hit.geometricNormal : hit.geometricNormal;
  const Vec3f n = back ? -hit.shadingNormal : hit.shadingNormal;
  sp.frame = viewerFrame(mapNormal(scene, hit, m.normalTexture, m.normalScale, n), wo, sp.geometricNormal);

  // glTF: base colour = factor * texture * COLOR_0 (alpha is the scene's alpha filter's job).
  BsdfParams& base = sp.bsdf.base;
  const Vec4f bc = lookup(scene, m.baseColorTexture, hit);
  sp.albedo = Rgb{m.baseColor.x * bc.x * hit.color.x, m.baseColor.y * bc.y * hit.color.y,
                  m.baseColor.z * bc.z * hit.color.z};
  base.baseColor = lambda.reflectance(sp.albedo);
  const Vec4f mr = lookup(scene, m.metallicRoughnessTexture, hit);
  base.roughness = std::clamp(m.roughness * mr.y, 0.0f, 1.0f);
  base.metallic = std::clamp(m.metallic * mr.z, 0.0f, 1.0f);
  base.ior = m.ior;
  base.specularWeight = std::clamp(m.specular * lookup(scene, m.specularTexture, hit).w, 0.0f, 1.0f) *
                        materials.extra(hit.material).specularWeight;
  base.specularColor = lambda.unbounded(m.specularColor * rgb(lookup(scene, m.specularColorTexture, hit)));

  if (m.transmission > 0) {
    GltfBsdfParams& b = sp.bsdf;
    b.transmission = std::clamp(m.transmission * lookup(scene, m.transmissionTexture, hit).x, 0.0f, 1.0f);
    b.dielectric.thin = m.thinWalled();
    // KHR_materials_dispersion: the index at the hero wavelength (the
    // integrator has dropped the other wavelengths at this hit).
    const float ior = std::max(1.0f, lambda.spectral() ? m.iorAt(lambda.hero()) : m.ior);
    b.dielectric.eta = b.dielectric.thin || !back ? ior : 1 / ior;
    b.dielectric.roughness = base.roughness;
    b.dielectric.tint = base.baseColor;
    b.dielectric.specularWeight = base.specularWeight;
    b.dielectric.specularColor = base.specularColor;
  }
  if (m.clearcoat > 0) {
    sp.bsdf.clearcoat = std::clamp(m.clearcoat * lookup(scene, m.clearcoatTexture, hit).x, 0.0f, 1.0f);
    sp.bsdf.clearcoatRoughness =
        std::clamp(m.clearcoatRoughness * lookup(scene, m.clearcoatRoughnessTexture, hit).y, 0.0f, 1.0f);
    // The coat has its own normal map; without one it follows the geometry,
    // not the base's normal map.
    sp.coatFrame = viewerFrame(mapNormal(scene, hit, m.clearcoatNormalTexture, m.clearcoatNormalScale, n), wo,
                               sp.geometricNormal);
  } else {
    sp.coatFrame = sp.frame;
  }
  if (maxComponent(m.sheenColor) > 0) {
    // glTF's sheen colour is a reflectance in [0, 1] (unlike specularColorFactor).
    sp.bsdf.sheenColor =
        lambda.reflectance(min(m.sheenColor * rgb(lookup(scene, m.sheenColorTexture, hit)), Rgb{1, 1, 1}));
    sp.bsdf.sheenRoughness =
        std::clamp(m.sheenRoughness * lookup(scene, m.sheenRoughnessTexture, hit).w, 0.0f, 1.0f);
  }
  const Rgb emission =
      emittedRadiance(materials, hit.material, hit.uv, hit.uv1, dot(wo, hit.geometricNormal));
  if (maxComponent(emission) > 0) sp.emission = lambda.illuminant(emission);
  return sp;
}

}  // namespace lensrt
