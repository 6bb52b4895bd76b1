// Material evaluation: factors times textures, and normal maps in glTF's
// tangent space (+X along u, +Y toward decreasing v, i.e. up in the image).
#include "render/material_eval.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lensrt {
namespace {

// A quad in y = 0 facing +Y whose u runs along +X and v along +Z, with a 1x1
// normal texture holding the tangent-space normal `n`.
SceneDesc normalMappedQuad(const Vec3f& n, bool withTangents) {
  SceneDesc s;
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  if (withTangents) m.tangents.assign(4, Vec4f{1, 0, 0, 1});  // +X, bitangent cross(N,T) = -Z
  m.indices = {0, 2, 1, 0, 3, 2};
  m.material = 0;
  s.meshes.push_back(m);
  s.instances.push_back({0, Transform()});
  Texture t;
  t.width = t.height = 1;
  t.texels = {{0.5f * (n.x + 1), 0.5f * (n.y + 1), 0.5f * (n.z + 1), 1}};
  s.textures.push_back(t);
  Material mat;
  mat.baseColor = {0.5f, 0.25f, 1, 1};
  mat.metallic = 0.3f;
  mat.roughness = 0.7f;
  mat.normalTexture.texture = 0;
  s.materials.push_back(mat);
  return s;
}

SurfaceHit hitOnQuad(const Vec4f& tangent) {
  SurfaceHit h;
  h.position = {0.4f, 0, 0.3f};
  h.geometricNormal = h.shadingNormal = {0, 1, 0};
  h.tangent = tangent;
  h.uv = {0.4f, 0.3f};
  h.material = 0;
  h.instance = 0;
  h.primitive = 0;
  return h;
}

TEST(MaterialEval, FactorsAndNormalMapFollowGltfTangentSpace) {
  const float s = std::sin(0.5f), c = std::cos(0.5f);
  // Tilt toward +u (tangent): the world normal leans toward +X.
  // Tilt toward +Y of the map (up in the image = decreasing v = -Z here).
  struct Case {
    Vec3f mapNormal, expectedWorld;
  };
  for (const Case& k : {Case{{s, 0, c}, {s, c, 0}}, Case{{0, s, c}, {0, c, -s}}}) {
    for (bool withTangents : {true, false}) {
      const SceneDesc scene = normalMappedQuad(k.mapNormal, withTangents);
      const MaterialTable materials(scene);
      const SurfaceHit hit = hitOnQuad(withTangents ? Vec4f{1, 0, 0, 1} : Vec4f{0, 0, 0, 0});
      const ShadingPoint sp = evaluateMaterial(materials, hit, normalize(Vec3f{0.1f, 1, 0.2f}));
      EXPECT_NEAR(sp.frame.n.x, k.expectedWorld.x, 1e-2f) << (withTangents ? "TANGENT" : "from uvs");
      EXPECT_NEAR(sp.frame.n.y, k.expectedWorld.y, 1e-2f) << (withTangents ? "TANGENT" : "from uvs");
      EXPECT_NEAR(sp.frame.n.z, k.expectedWorld.z, 1e-2f) << (withTangents ? "TANGENT" : "from uvs");
      EXPECT_FLOAT_EQ(sp.bsdf.base.baseColor[1], 0.25f);
      EXPECT_FLOAT_EQ(sp.bsdf.base.metallic, 0.3f);
      EXPECT_FLOAT_EQ(sp.bsdf.base.roughness, 0.7f);
    }
  }
}

// A KHR_texture_transform on the normal map turns a vertex TANGENT frame as
// it turns the frame derived from the uvs: rotated, mirrored, sheared.
TEST(MaterialEval, TextureTransformTurnsTheTangentFrameEitherWay) {
  const float s = std::sin(0.5f), c = std::cos(0.5f);
  const UvTransform transforms[] = {UvTransform::fromOffsetRotationScale({0.1f, 0.2f}, 0.7f, {1, 1}),
                                    UvTransform::fromOffsetRotationScale({0, 0}, 0.0f, {-1, 1}),
                                    UvTransform::fromOffsetRotationScale({0.3f, 0}, -2.0f, {2, -0.5f}),
                                    UvTransform{{1, 0.4f, 0, 0, 1, 0}}};
  for (const Vec3f& mapNormal : {Vec3f{s, 0, c}, Vec3f{0, s, c}})
    for (const UvTransform& x : transforms) {
      Vec3f normals[2];
      for (const bool withTangents : {true, false}) {
        SceneDesc scene = normalMappedQuad(mapNormal, withTangents);
        scene.materials[0].normalTexture.transform = x;
        const SurfaceHit hit = hitOnQuad(withTangents ? Vec4f{1, 0, 0, 1} : Vec4f{0, 0, 0, 0});
        normals[withTangents] =
            evaluateMaterial(MaterialTable(scene), hit, normalize(Vec3f{0.1f, 1, 0.2f})).frame.n;
      }
      EXPECT_NEAR(normals[1].x, normals[0].x, 1e-5f);
      EXPECT_NEAR(normals[1].y, normals[0].y, 1e-5f);
      EXPECT_NEAR(normals[1].z, normals[0].z, 1e-5f);
      // And the map does tilt the normal (the test would pass vacuously otherwise).
      EXPECT_LT(normals[1].y, 0.95f);
    }
}

TEST(MaterialEval, EmissionIsFrontFacingUnlessDoubleSided) {
  SceneDesc scene = normalMappedQuad({0, 0, 1}, true);
  scene.materials[0].emissive = {2, 3, 4};
  const MaterialTable materials(scene);
  EXPECT_EQ(emittedRadiance(materials, 0, {0.5f, 0.5f}, {0.5f, 0.5f}, 0.5f), Rgb(2, 3, 4));
  EXPECT_EQ(emittedRadiance(materials, 0, {0.5f, 0.5f}, {0.5f, 0.5f}, -0.5f), Rgb(0, 0, 0));
  scene.materials[0].doubleSided = true;
  EXPECT_EQ(emittedRadiance(MaterialTable(scene), 0, {0.5f, 0.5f}, {0.5f, 0.5f}, -0.5f), Rgb(2, 3, 4));
}

}  // namespace
}  // namespace lensrt

namespace lensrt {
namespace {

// 2x1 nearest texture: texel 0 red 0.2, texel 1 red 0.8 (u < 0.5 and u > 0.5).
SceneDesc twoTexelBaseColour(const TextureRef& ref) {
  SceneDesc s = normalMappedQuad({0, 0, 1}, true);
  Texture t;
  t.width = 2;
  t.height = 1;
  t.nearest = true;
  t.texels = {{0.2f, 1, 1, 1}, {0.8f, 1, 1, 1}};
  s.textures.push_back(t);
  s.materials[0].normalTexture = {};
  s.materials[0].baseColor = {1, 1, 1, 1};
  s.materials[0].baseColorTexture = ref;
  s.materials[0].baseColorTexture.texture = 1;
  return s;
}

TEST(MaterialEval, VertexColourMultipliesTheBaseColour) {
  SceneDesc scene = normalMappedQuad({0, 0, 1}, true);
  const MaterialTable materials(scene);
  SurfaceHit hit = hitOnQuad({1, 0, 0, 1});
  hit.color = {0.5f, 0.5f, 0.25f, 1};
  const ShadingPoint sp = evaluateMaterial(materials, hit, {0, 1, 0});
  // factor (0.5, 0.25, 1) times COLOR_0 (0.5, 0.5, 0.25).
  EXPECT_FLOAT_EQ(sp.bsdf.base.baseColor[0], 0.25f);
  EXPECT_FLOAT_EQ(sp.bsdf.base.baseColor[1], 0.125f);
  EXPECT_FLOAT_EQ(sp.bsdf.base.baseColor[2], 0.25f);
}

TEST(MaterialEval, TextureSlotsReadTheirUvSetThroughTheirTransform) {
  SurfaceHit hit = hitOnQuad({1, 0, 0, 1});
  hit.uv = {0.25f, 0.5f};
  hit.uv1 = {0.75f, 0.5f};
  TextureRef ref;
  EXPECT_FLOAT_EQ(
      evaluateMaterial(MaterialTable(twoTexelBaseColour(ref)), hit, {0, 1, 0}).bsdf.base.baseColor[0], 0.2f);
  ref.texCoord = 1;
  EXPECT_FLOAT_EQ(
      evaluateMaterial(MaterialTable(twoTexelBaseColour(ref)), hit, {0, 1, 0}).bsdf.base.baseColor[0], 0.8f);
  // Offset -0.5 on TEXCOORD_1: u = 0.25, texel 0.
  ref.transform = UvTransform::fromOffsetRotationScale({-0.5f, 0}, 0, {1, 1});
  EXPECT_FLOAT_EQ(
      evaluateMaterial(MaterialTable(twoTexelBaseColour(ref)), hit, {0, 1, 0}).bsdf.base.baseColor[0], 0.2f);
}

TEST(MaterialEval, RotatedNormalMapTurnsTheFrameDerivedFromUvs) {
  // Rotation 90 degrees: u' = v (world +Z), v' = -u, so the map's +X points
  // along world +Z and its +Y (toward decreasing v') along world +X.
  const float s = std::sin(0.5f), c = std::cos(0.5f);
  struct Case {
    Vec3f mapNormal, expectedWorld;
  };
  for (const Case& k : {Case{{s, 0, c}, {0, c, s}}, Case{{0, s, c}, {s, c, 0}}}) {
    SceneDesc scene = normalMappedQuad(k.mapNormal, false);
    scene.materials[0].normalTexture.transform =
        UvTransform::fromOffsetRotationScale({0, 0}, 1.5707963f, {1, 1});
    const ShadingPoint sp =
        evaluateMaterial(MaterialTable(scene), hitOnQuad({0, 0, 0, 0}), normalize(Vec3f{0.1f, 1, 0.2f}));
    EXPECT_NEAR(sp.frame.n.x, k.expectedWorld.x, 1e-2f);
    EXPECT_NEAR(sp.frame.n.y, k.expectedWorld.y, 1e-2f);
    EXPECT_NEAR(sp.frame.n.z, k.expectedWorld.z, 1e-2f);
  }
}

}  // namespace
}  // namespace lensrt
