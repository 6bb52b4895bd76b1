// Loader geometry: primitive modes, index types, accessors, hierarchy, instancing.
#include <gtest/gtest.h>

#include <cmath>

#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

SceneDesc load(const GltfBuilder& b, Warnings& w, int scene = -1) {
  return loadGltf(test::writeFile(test::testDir() / "scene.gltf", b.json()), scene, w);
}
SceneDesc load(const GltfBuilder& b, int scene = -1) {
  Warnings w;
  return load(b, w, scene);
}

void expectVec(const Vec3f& a, const Vec3f& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// Signed areas (z of the CCW cross product / 2) of a mesh's triangles.
std::vector<float> signedAreas(const Mesh& m) {
  std::vector<float> areas;
  for (std::size_t t = 0; t < m.triangleCount(); ++t) {
    const Vec3f a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                c = m.positions[m.indices[3 * t + 2]];
    areas.push_back(0.5f * cross(b - a, c - a).z);
  }
  return areas;
}

Ray down(float x, float y) {
  return {{x, y, 50}, {0, 0, -1}};
}

TEST(GltfGeometry, NonIndexedTriangles) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}})}});
  const SceneDesc d = load(b);
  ASSERT_EQ(d.meshes.size(), 1u);
  EXPECT_EQ(d.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
  ASSERT_EQ(d.instances.size(), 1u);
  EXPECT_TRUE(d.cameras.empty());
}

TEST(GltfGeometry, IndexComponentTypesAgree) {
  for (int type : {5121, 5123, 5125}) {
    SCOPED_TRACE(type);
    GltfBuilder b;
    const int pos = b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
    const int idx = type == 5121   ? b.u8({0, 1, 2, 0, 2, 3})
                    : type == 5123 ? b.u16({0, 1, 2, 0, 2, 3})
                                   : b.u32({0, 1, 2, 0, 2, 3});
    b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}})}});
    const SceneDesc d = load(b);
    EXPECT_EQ(d.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
  }
}

TEST(GltfGeometry, TriangleStripKeepsWinding) {
  GltfBuilder b;
  // Zig-zag strip over the unit square plus one more cell: 3 triangles.
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0}, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}, {"mode", 5}})}});
  const SceneDesc d = load(b);
  const std::vector<float> areas = signedAreas(d.meshes[0]);
  ASSERT_EQ(areas.size(), 3u);
  for (float a : areas) EXPECT_NEAR(a, 0.5f, 1e-6f);  // all counter-clockwise from +Z
}

TEST(GltfGeometry, IndexedTriangleFan) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0}, "VEC3");
  const int idx = b.u16({0, 1, 2, 3, 4});
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", idx}, {"mode", 6}})}});
  const SceneDesc d = load(b);
  const std::vector<float> areas = signedAreas(d.meshes[0]);
  ASSERT_EQ(areas.size(), 3u);
  for (float a : areas) EXPECT_NEAR(a, 0.5f, 1e-6f);
  for (std::size_t t = 0; t < 3; ++t)
    EXPECT_EQ(d.meshes[0].indices[3 * t + 2], 0u);  // every triangle has the hub
}

TEST(GltfGeometry, LinesAndPointsAreSkippedWithOneWarning) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  json m = {{"primitives",
             {{{"attributes", {{"POSITION", pos}}}, {"mode", 1}},
              {{"attributes", {{"POSITION", pos}}}, {"mode", 0}},
              {{"attributes", {{"POSITION", pos}}}, {"mode", 1}},
              {{"attributes", {{"POSITION", pos}}}}}}};
  b.doc["meshes"].push_back(m);
  b.node({{"mesh", 0}});
  Warnings w;
  const SceneDesc d = load(b, w);
  EXPECT_EQ(d.meshes.size(), 1u);
  EXPECT_EQ(w.all().count("primitive mode LINES is not rendered (skipped)"), 1u);
  EXPECT_EQ(w.all().count("primitive mode POINTS is not rendered (skipped)"), 1u);
}

TEST(GltfGeometry, NodeHierarchyComposesParentThenChild) {
  GltfBuilder b;
  const int square = b.square();
  const double s = std::sqrt(0.5);
  const int child = b.node({{"mesh", square}, {"rotation", {0, 0, s, s}}}, false);  // +90 deg about Z
  b.node({{"children", {child}}, {"translation", {10, 0, 0}}, {"scale", {2, 2, 2}}});
  const SceneDesc d = load(b);
  ASSERT_EQ(d.instances.size(), 1u);
  // (1,0,0) -> rotate (0,1,0) -> scale (0,2,0) -> translate (10,2,0).
  expectVec(d.instances[0].worldFromObject.point(Vec3f{1, 0, 0}), {10, 2, 0});
  const RenderScene scene(SceneDesc{d});
  EXPECT_TRUE(scene.intersect(down(9, 1)));
  EXPECT_FALSE(scene.intersect(down(10.5f, 1)));
}

TEST(GltfGeometry, MatrixNodeIsColumnMajor) {
  GltfBuilder b;
  b.node({{"mesh", b.square()}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 4, 5, 6, 1}}});
  expectVec(load(b).instances[0].worldFromObject.point(Vec3f{0, 0, 0}), {4, 5, 6});
}

TEST(GltfGeometry, RepeatedMeshBecomesInstances) {
  GltfBuilder b;
  const int square = b.square();
  b.node({{"mesh", square}, {"translation", {-5, 0, 0}}});
  b.node({{"mesh", square}, {"translation", {5, 0, 0}}});
  SceneDesc d = load(b);
  EXPECT_EQ(d.meshes.size(), 1u);
  ASSERT_EQ(d.instances.size(), 2u);
  const RenderScene scene(std::move(d));
  EXPECT_EQ(scene.stats().embreeInstances, 2);
  EXPECT_EQ(scene.stats().sharedMeshes, 1);
  const auto left = scene.intersect(down(-4.5f, 0.5f));
  const auto right = scene.intersect(down(5.5f, 0.5f));
  ASSERT_TRUE(left && right);
  EXPECT_EQ(left->instance, 0);
  EXPECT_EQ(right->instance, 1);
  EXPECT_FALSE(scene.intersect(down(0.5f, 0.5f)));
}

TEST(GltfGeometry, ExtMeshGpuInstancing) {
  GltfBuilder b;
  b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  const int square = b.square();
  const int t = b.floats({0, 0, 0, 5, 0, 0, 10, 0, 0}, "VEC3");
  const int s = b.floats({1, 1, 1, 2, 2, 2, 1, 1, 1}, "VEC3");
  const float h = std::sqrt(0.5f);
  const int r = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, h, h}, "VEC4");  // last: +90 deg about Z
  b.node({{"mesh", square},
          {"translation", {0, 0, 1}},
          {"extensions",
           {{"EXT_mesh_gpu_instancing",
             {{"attributes", {{"TRANSLATION", t}, {"ROTATION", r}, {"SCALE", s}}}}}}}});
  Warnings w;
  SceneDesc d = load(b, w);
  EXPECT_TRUE(w.all().empty());
  ASSERT_EQ(d.instances.size(), 3u);
  expectVec(d.instances[1].worldFromObject.point(Vec3f{1, 1, 0}), {7, 2, 1});
  expectVec(d.instances[2].worldFromObject.point(Vec3f{1, 0, 0}), {10, 1, 1});
  const RenderScene scene(std::move(d));
  EXPECT_EQ(scene.stats().embreeInstances, 3);
  EXPECT_EQ(scene.intersect(down(0.5f, 0.5f))->instance, 0);
  EXPECT_EQ(scene.intersect(down(6.5f, 1.5f))->instance, 1);
  EXPECT_EQ(scene.intersect(down(9.5f, 0.5f))->instance, 2);
  EXPECT_FALSE(scene.intersect(down(10.5f, 0.5f)));  // rotated away from +x
}

TEST(GltfGeometry, DefaultSceneAndSceneIndex) {
  GltfBuilder b;
  const int square = b.square();
  b.node({{"mesh", square}});
  const int far = b.node({{"mesh", square}, {"translation", {0, 0, 7}}}, false);
  b.doc["scenes"].push_back({{"nodes", {far}}});
  b.doc["scene"] = 1;
  EXPECT_NEAR(load(b).worldBounds().lo.z, 7, 1e-6);
  EXPECT_NEAR(load(b, 0).worldBounds().lo.z, 0, 1e-6);
}

TEST(GltfGeometry, SparseAccessorSubstitutesValues) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  const std::vector<std::uint16_t> which{2};
  const std::vector<float> values{3, 3, 0};
  const int iv = b.view(which.data(), 2);
  const int vv = b.view(values.data(), 12);
  b.doc["accessors"][pos]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", iv}, {"componentType", 5123}}},
                                       {"values", {{"bufferView", vv}}}};
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", b.u16({0, 1, 2, 0, 2, 3})}})}});
  const SceneDesc d = load(b);
  expectVec(d.meshes[0].positions[2], {3, 3, 0});
  expectVec(d.meshes[0].positions[1], {1, 0, 0});
}

TEST(GltfGeometry, NormalizedIntegerTexcoords) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int uv16 = b.u16({0, 65535, 32768, 0, 65535, 65535}, "VEC2", true);
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv16}}}})}});
  const SceneDesc d = load(b);
  EXPECT_EQ(d.meshes[0].uvs[0].y, 1.0f);
  EXPECT_NEAR(d.meshes[0].uvs[1].x, 32768.0f / 65535.0f, 1e-7f);
}

TEST(GltfGeometry, InterleavedByteStride) {
  GltfBuilder b;
  // position, normal interleaved: 24-byte stride.
  const std::vector<float> data{0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1};
  const int view = b.view(data.data(), data.size() * 4, 24);
  b.doc["accessors"].push_back(
      {{"bufferView", view}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  b.doc["accessors"].push_back(
      {{"bufferView", view}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}})}});
  const SceneDesc d = load(b);
  expectVec(d.meshes[0].positions[2], {0, 1, 0});
  expectVec(d.meshes[0].normals[1], {0, 0, 1});
}

TEST(GltfGeometry, BinaryGlbLoads) {
  GltfBuilder b;
  b.node({{"mesh", b.square()}, {"translation", {0, 0, 2}}});
  Warnings w;
  const SceneDesc d = loadGltf(test::writeFile(test::testDir() / "scene.glb", b.glb()), -1, w);
  EXPECT_EQ(d.meshes[0].triangleCount(), 2u);
  EXPECT_NEAR(d.worldBounds().hi.z, 2, 1e-6);
}

TEST(GltfGeometry, MirroredNodeKeepsFrontFaceAndFlipsShadingNormal) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  // Vertex normals point against the winding (-Z): the hit reports them flipped.
  const int nrm = b.floats({0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1}, "VEC3");
  const int square =
      b.mesh({{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}}, {"indices", b.u16({0, 1, 2, 0, 2, 3})}});
  b.node({{"mesh", square}, {"scale", {-1, 1, 1}}});
  const RenderScene scene(load(b));
  const auto hit = scene.intersect(down(-0.5f, 0.5f));
  ASSERT_TRUE(hit);
  expectVec(hit->geometricNormal, {0, 0, 1});  // mirrored: clockwise is the front
  expectVec(hit->shadingNormal, {0, 0, 1});
}

}  // namespace
}  // namespace lensrt
