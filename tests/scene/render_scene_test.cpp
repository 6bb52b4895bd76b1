#include "scene/render_scene.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "core/error.h"

namespace lensrt {
namespace {

// Unit quad in the z = 0 plane, counter-clockwise seen from +Z, uv (0,0) at (-1,-1).
Mesh quad() {
  Mesh m;
  m.name = "quad";
  m.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

SceneDesc oneQuad(const Transform& xf = Transform()) {
  SceneDesc d;
  d.sourceFile = "test.gltf";
  d.meshes.push_back(quad());
  d.instances.push_back({0, xf});
  return d;
}

Ray down(float x, float y, float z = 5) {
  return {{x, y, z}, {0, 0, -1}};
}

void expectVec(const Vec3f& a, const Vec3f& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(RenderScene, HitsQuadWithPositionNormalAndUv) {
  const RenderScene scene(oneQuad(Transform::translate({0, 0, 1})));
  const auto hit = scene.intersect(down(0.5f, -0.5f));
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 4.0f, 1e-5f);
  expectVec(hit->position, {0.5f, -0.5f, 1});
  expectVec(hit->geometricNormal, {0, 0, 1});
  expectVec(hit->shadingNormal, {0, 0, 1});
  EXPECT_NEAR(hit->uv.x, 0.75f, 1e-5f);
  EXPECT_NEAR(hit->uv.y, 0.25f, 1e-5f);
  EXPECT_EQ(hit->instance, 0);
  EXPECT_EQ(hit->material, -1);
  EXPECT_FALSE(scene.intersect(down(1.5f, 0)));
  EXPECT_EQ(scene.stats().bakedGeometries, 1);
  EXPECT_EQ(scene.stats().embreeInstances, 0);
}

TEST(RenderScene, RespectsRayInterval) {
  const RenderScene scene(oneQuad());
  Ray r = down(0, 0);
  r.tMax = 4.9f;
  EXPECT_FALSE(scene.intersect(r));
  EXPECT_FALSE(scene.occluded(r));
  r.tMax = 5.1f;
  EXPECT_TRUE(scene.occluded(r));
  r.tMin = 5.05f;
  EXPECT_FALSE(scene.occluded(r));
}

TEST(RenderScene, MirroredTransformKeepsOutwardNormal) {
  // Mirroring x turns the winding clockwise; glTF says the front face follows
  // the determinant, so the surface still faces +Z.
  const RenderScene scene(oneQuad(Transform::scale({-1, 1, 1})));
  const auto hit = scene.intersect(down(0.25f, 0.5f));
  ASSERT_TRUE(hit);
  expectVec(hit->geometricNormal, {0, 0, 1});
  EXPECT_NEAR(hit->uv.x, 0.375f, 1e-5f);  // x = 0.25 came from object x = -0.25
}

TEST(RenderScene, RotationTurnsTheNormal) {
  const double s = std::sqrt(0.5);
  const RenderScene scene(oneQuad(Transform::rotateQuaternion(0, s, 0, s)));  // +Z -> +X
  const auto hit = scene.intersect({{5, 0.2f, 0.3f}, {-1, 0, 0}});
  ASSERT_TRUE(hit);
  expectVec(hit->geometricNormal, {1, 0, 0});
  expectVec(hit->position, {0, 0.2f, 0.3f});
}

TEST(RenderScene, ShadingNormalFlipsIntoGeometricHemisphere) {
  SceneDesc d = oneQuad();
  // Vertex normals tilted and pointing below the surface: the hit must report
  // them flipped to the +Z side.
  const Vec3f n = normalize(Vec3f{0.6f, 0, -0.8f});
  d.meshes[0].normals.assign(4, n);
  const RenderScene scene(std::move(d));
  const auto hit = scene.intersect(down(0, 0));
  ASSERT_TRUE(hit);
  expectVec(hit->shadingNormal, {-0.6f, 0, 0.8f});
}

TEST(RenderScene, NonUniformScaleTransformsNormalsByInverseTranspose) {
  SceneDesc d = oneQuad(Transform::scale({1, 4, 1}));
  d.meshes[0].normals.assign(4, normalize(Vec3f{0, 1, 1}));
  const RenderScene scene(std::move(d));
  const auto hit = scene.intersect(down(0, 0));
  ASSERT_TRUE(hit);
  // (0,1,1) under the inverse transpose of diag(1,4,1) is (0,1/4,1).
  expectVec(hit->shadingNormal, normalize(Vec3f{0, 0.25f, 1}));
}

TEST(RenderScene, TangentFollowsTransformAndMirrorFlipsHandedness) {
  SceneDesc d = oneQuad(Transform::scale({-1, 1, 1}));
  d.meshes[0].tangents.assign(4, Vec4f{1, 0, 0, 1});
  const RenderScene scene(std::move(d));
  const auto hit = scene.intersect(down(0, 0));
  ASSERT_TRUE(hit);
  expectVec(hit->tangent.xyz(), {-1, 0, 0});
  EXPECT_EQ(hit->tangent.w, -1.0f);
}

TEST(RenderScene, SharedMeshBecomesEmbreeInstancesHitOnBothCopies) {
  SceneDesc d;
  d.meshes.push_back(quad());
  d.instances.push_back({0, Transform::translate({-5, 0, 0})});
  d.instances.push_back({0, Transform::translate({5, 0, 0}) * Transform::scale({2, 2, 2})});
  const RenderScene scene(std::move(d));
  EXPECT_EQ(scene.stats().sharedMeshes, 1);
  EXPECT_EQ(scene.stats().embreeInstances, 2);
  EXPECT_EQ(scene.stats().bakedGeometries, 0);
  const auto left = scene.intersect(down(-5.5f, 0.5f));
  ASSERT_TRUE(left);
  EXPECT_EQ(left->instance, 0);
  expectVec(left->position, {-5.5f, 0.5f, 0});
  EXPECT_NEAR(left->uv.x, 0.25f, 1e-5f);
  const auto right = scene.intersect(down(6.5f, 0));  // only inside because of the scale 2
  ASSERT_TRUE(right);
  EXPECT_EQ(right->instance, 1);
  expectVec(right->position, {6.5f, 0, 0});
  EXPECT_NEAR(right->uv.x, 0.875f, 1e-5f);
  expectVec(right->geometricNormal, {0, 0, 1});
  EXPECT_FALSE(scene.intersect(down(0, 0)));
  const Bounds3f b = scene.bounds();
  EXPECT_NEAR(b.lo.x, -6, 1e-4f);
  EXPECT_NEAR(b.hi.x, 7, 1e-4f);
}

// Embree inverts instance transforms in float and aborts (ray.valid()) when
// a ray leaves float range in instance space; a flat quad squashed by 1e-20
// along z and stretched by 1e8 in x (fuzz_gltf found such placements) is
// baked into world space instead, and is hit exactly where its world-space
// corners say.
TEST(RenderScene, ExtremePlacementsOfASharedMeshAreBakedNotInstanced) {
  SceneDesc d;
  d.meshes.push_back(quad());
  d.instances.push_back({0, Transform::translate({-5, 0, 0})});
  d.instances.push_back({0, Transform::translate({0, 0, 2})});
  d.instances.push_back({0, Transform::translate({0, 20, 0}) * Transform::scale({1e8, 1, 1e-20})});
  const RenderScene scene(std::move(d));
  EXPECT_EQ(scene.stats().sharedMeshes, 1);
  EXPECT_EQ(scene.stats().embreeInstances, 2);
  EXPECT_EQ(scene.stats().bakedGeometries, 1);
  // The stretched quad spans x in [-1e8, 1e8], y in [19, 21] at z = 0.
  const auto far = scene.intersect(down(5e7f, 20.5f));
  ASSERT_TRUE(far);
  EXPECT_EQ(far->instance, 2);
  EXPECT_NEAR(far->t, 5.0f, 1e-4f);
  expectVec(far->geometricNormal, {0, 0, 1});
  EXPECT_FALSE(scene.intersect(down(5e7f, 21.5f)));
  // The two well-scaled copies stay Embree instances and are hit where placed.
  const auto left = scene.intersect(down(-5.5f, 0.5f));
  ASSERT_TRUE(left);
  EXPECT_EQ(left->instance, 0);
  const auto raised = scene.intersect(down(0.5f, 0.5f));
  ASSERT_TRUE(raised);
  EXPECT_EQ(raised->instance, 1);
  EXPECT_NEAR(raised->t, 3.0f, 1e-5f);
}

// Material with a 2x1 nearest texture: left texel transparent, right opaque.
SceneDesc maskedQuadOverFloor(AlphaMode mode, float cutoff, float leftAlpha) {
  SceneDesc d = oneQuad(Transform::translate({0, 0, 1}));
  Texture t;
  t.width = 2;
  t.height = 1;
  t.nearest = true;
  t.texels = {{1, 1, 1, leftAlpha}, {1, 1, 1, 1}};
  d.textures.push_back(t);
  Material m;
  m.alphaMode = mode;
  m.alphaCutoff = cutoff;
  m.baseColorTexture.texture = 0;
  d.materials.push_back(m);
  d.meshes[0].material = 0;
  d.meshes.push_back(quad());  // the floor at z = 0, opaque default material
  d.instances.push_back({1, Transform()});
  return d;
}

TEST(RenderScene, AlphaMaskLetsRaysThroughTransparentTexels) {
  const RenderScene scene(maskedQuadOverFloor(AlphaMode::Mask, 0.5f, 0.2f));
  const auto through = scene.intersect(down(-0.5f, 0));
  ASSERT_TRUE(through);
  EXPECT_EQ(through->instance, 1);  // the floor under the transparent half
  EXPECT_NEAR(through->t, 5.0f, 1e-5f);
  const auto blocked = scene.intersect(down(0.5f, 0));
  ASSERT_TRUE(blocked);
  EXPECT_EQ(blocked->instance, 0);
  EXPECT_EQ(blocked->material, 0);
  // Shadow rays between the two layers see the same cut-out.
  Ray shadowLeft = down(-0.5f, 0);
  shadowLeft.tMax = 4.5f;
  EXPECT_FALSE(scene.occluded(shadowLeft));
  Ray shadowRight = down(0.5f, 0);
  shadowRight.tMax = 4.5f;
  EXPECT_TRUE(scene.occluded(shadowRight));
}

TEST(RenderScene, AlphaCutoffComparesAgainstTexelAlpha) {
  // alpha 0.2 is opaque for a cutoff of 0.1.
  const RenderScene scene(maskedQuadOverFloor(AlphaMode::Mask, 0.1f, 0.2f));
  EXPECT_EQ(scene.intersect(down(-0.5f, 0))->instance, 0);
}

// Fraction of n distinct rays down through the left (alpha = leftAlpha) half
// of a BLEND quad that reach the floor, by intersection and by occlusion.
std::pair<double, double> blendTransmission(const RenderScene& scene, int n) {
  int through = 0, unblocked = 0;
  for (int i = 0; i < n; ++i) {
    // Distinct rays spread over the transparent half, away from its edges.
    const float x = -0.9f + 0.8f * static_cast<float>(i % 64) / 64.0f;
    const float y = -0.9f + 1.8f * static_cast<float>(i / 64) / static_cast<float>(n / 64);
    const auto hit = scene.intersect(down(x, y));
    if (hit && hit->instance == 1) ++through;
    Ray shadow = down(x, y);
    shadow.tMax = 4.5f;  // from above the quad to between quad and floor
    if (!scene.occluded(shadow)) ++unblocked;
  }
  return {double(through) / n, double(unblocked) / n};
}

TEST(RenderScene, BlendLetsOneMinusAlphaOfTheRaysThrough) {
  constexpr int kN = 8192;  // binomial sigma at p = 0.75: 0.0048
  for (const float alpha : {0.25f, 0.6f}) {
    const RenderScene scene(maskedQuadOverFloor(AlphaMode::Blend, 0.5f, alpha));
    const auto [through, unblocked] = blendTransmission(scene, kN);
    EXPECT_NEAR(through, 1 - alpha, 0.025) << alpha;
    EXPECT_NEAR(unblocked, 1 - alpha, 0.025) << alpha;
  }
  // The opaque half stays opaque, and the alpha cutoff plays no part.
  const RenderScene scene(maskedQuadOverFloor(AlphaMode::Blend, 0.9f, 0.25f));
  EXPECT_EQ(scene.intersect(down(0.5f, 0.3f))->instance, 0);
}

TEST(RenderScene, BlendDecisionIsAFunctionOfTheRay) {
  const RenderScene scene(maskedQuadOverFloor(AlphaMode::Blend, 0.5f, 0.5f));
  int differ = 0;
  for (int i = 0; i < 256; ++i) {
    const Ray r = down(-0.9f + 0.003f * static_cast<float>(i), 0.2f);
    const bool first = scene.intersect(r)->instance == 1;
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(scene.intersect(r)->instance == 1, first);
      Ray shadow = r;
      shadow.tMax = 4.5f;
      EXPECT_EQ(!scene.occluded(shadow), first);  // the same ray (up to its end) meets the same surface
    }
    differ +=
        first != (scene.intersect(down(-0.9f + 0.003f * static_cast<float>(i), 0.2001f))->instance == 1);
  }
  EXPECT_GT(differ, 64);  // neighbouring rays decide independently (about half of them differ)
}

TEST(RenderScene, OpaqueModeIgnoresAlpha) {
  const RenderScene scene(maskedQuadOverFloor(AlphaMode::Opaque, 0.5f, 0.0f));
  EXPECT_EQ(scene.intersect(down(-0.5f, 0))->instance, 0);
}

TEST(RenderScene, MaskedInstancesShareTheFilter) {
  SceneDesc d = maskedQuadOverFloor(AlphaMode::Mask, 0.5f, 0.0f);
  d.instances.push_back({0, Transform::translate({10, 0, 1})});
  const RenderScene scene(std::move(d));
  EXPECT_EQ(scene.stats().embreeInstances, 2);
  EXPECT_FALSE(scene.intersect(down(9.5f, 0)));  // transparent half, nothing behind
  const auto hit = scene.intersect(down(10.5f, 0));
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->instance, 2);
  EXPECT_EQ(scene.intersect(down(-0.5f, 0))->instance, 1);
}

// Threads querying one scene at once see what one thread sees, ray for ray.
// The mask's meaning is checked only away from its edge (x = 0, a texel
// boundary): a ray landing on the edge itself goes either way depending on
// Embree's floating-point path, which differs between CPUs (on AMD EPYC with
// AVX2 the i = 1000 ray at x = 0 was reported on the floor).
TEST(RenderScene, ConcurrentQueriesAgree) {
  const RenderScene scene(maskedQuadOverFloor(AlphaMode::Mask, 0.5f, 0.0f));
  constexpr int kRays = 2000;
  const auto rayX = [](int i) { return -0.99f + 1.98f * static_cast<float>(i) / kRays; };
  std::vector<int> serial(kRays, -1);
  int wrongAwayFromEdge = 0;
  for (int i = 0; i < kRays; ++i) {
    const float x = rayX(i);
    const auto hit = scene.intersect(down(x, 0.1f));
    serial[i] = hit ? hit->instance : -1;
    if (std::abs(x) > 0.01f && serial[i] != (x < 0 ? 1 : 0)) ++wrongAwayFromEdge;
  }
  EXPECT_EQ(wrongAwayFromEdge, 0);

  std::atomic<int> disagree{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < kRays; ++i) {
        const auto hit = scene.intersect(down(rayX(i), 0.1f));
        if ((hit ? hit->instance : -1) != serial[i]) ++disagree;
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(disagree.load(), 0);
}

// Sets LENSRT_EMBREE_CONFIG for one test and puts back what was there (the
// embree-isa ctest run sets it for the whole binary).
class ScopedEmbreeConfig {
 public:
  explicit ScopedEmbreeConfig(const char* value) {
    if (const char* old = std::getenv(kName)) saved_ = old;
    ::setenv(kName, value, 1);
  }
  ~ScopedEmbreeConfig() {
    if (saved_)
      ::setenv(kName, saved_->c_str(), 1);
    else
      ::unsetenv(kName);
  }
  ScopedEmbreeConfig(const ScopedEmbreeConfig&) = delete;
  ScopedEmbreeConfig& operator=(const ScopedEmbreeConfig&) = delete;

 private:
  static constexpr const char* kName = "LENSRT_EMBREE_CONFIG";
  std::optional<std::string> saved_;
};

// LENSRT_EMBREE_CONFIG reaches rtcNewDevice: Embree's verbose report names the
// instruction set the device was held to (CI runs the scene and render suites
// once more with isa=sse4.2, which is only worth anything if Embree obeys).
TEST(RenderScene, EmbreeConfigFromTheEnvironmentReachesTheDevice) {
  const ScopedEmbreeConfig config("verbose=1,isa=sse4.2");
  testing::internal::CaptureStdout();
  {
    const RenderScene scene(oneQuad());
    EXPECT_TRUE(scene.intersect(down(0.5f, -0.5f)));
  }
  const std::string report = testing::internal::GetCapturedStdout();
  // The report lists the CPU's ISA first, then the device's.
  const auto deviceIsa = report.rfind("ISA");
  ASSERT_NE(deviceIsa, std::string::npos) << report;
  const std::string line = report.substr(deviceIsa, report.find('\n', deviceIsa) - deviceIsa);
  EXPECT_NE(line.find("SSE4.2"), std::string::npos) << line;
  EXPECT_EQ(line.find("AVX"), std::string::npos) << line;
}

// A configuration Embree refuses is one error naming the variable.
TEST(RenderScene, EmbreeConfigThatEmbreeRefusesIsAnError) {
  if (__builtin_cpu_supports("avx512f")) GTEST_SKIP() << "this CPU has AVX-512: isa=avx512 is accepted";
  const ScopedEmbreeConfig config("isa=avx512");
  std::string message;
  try {
    const RenderScene scene(oneQuad());
  } catch (const InputError& e) {
    message = e.message();
  }
  EXPECT_EQ(message,
            "cannot create the Embree device with LENSRT_EMBREE_CONFIG='isa=avx512' (unsupported CPU)");
}

TEST(RenderScene, EmptySceneMissesEverything) {
  const RenderScene scene(SceneDesc{});
  EXPECT_FALSE(scene.intersect(down(0, 0)));
  EXPECT_FALSE(scene.occluded(down(0, 0)));
  EXPECT_TRUE(scene.bounds().empty());
}

TEST(RenderScene, RejectsIndexBeyondVertexCount) {
  SceneDesc d = oneQuad();
  d.meshes[0].indices[4] = 7;
  try {
    const RenderScene scene(std::move(d));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "test.gltf");
    EXPECT_EQ(e.message(), "mesh 'quad': index 7 beyond vertex count 4");
  }
}

TEST(RenderScene, RejectsNonFinitePositions) {
  SceneDesc d = oneQuad();
  d.meshes[0].positions[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(RenderScene{std::move(d)}, InputError);
}

}  // namespace
}  // namespace lensrt

namespace lensrt {
namespace {

// A bar from the origin to x = 1 (0.1 wide), turning 90 degrees about z
// during the shutter in two time steps, its normals leaning toward +x.
SceneDesc spinningBar(bool emissive) {
  SceneDesc d;
  d.sourceFile = "test.gltf";
  Mesh m;
  m.name = "bar";
  m.positions = {{0, -0.05f, 0}, {1, -0.05f, 0}, {1, 0.05f, 0}, {0, 0.05f, 0}};
  const float h = std::sqrt(0.5f);
  m.normals.assign(4, Vec3f{h, 0, h});
  m.indices = {0, 1, 2, 0, 2, 3};
  if (emissive) {
    Material glow;
    glow.emissive = {1, 1, 1};
    d.materials.push_back(glow);
    m.material = 0;
  }
  d.meshes.push_back(m);
  const Transform turned = Transform::rotateQuaternion(0, 0, std::sqrt(0.5), std::sqrt(0.5));
  d.instances.push_back({0, Transform(), {{0, Transform()}, {0, turned}}});
  d.motionSteps = 2;
  return d;
}

Ray downAt(float x, float y, float time) {
  Ray r = down(x, y);
  r.time = time;
  return r;
}

// A rigid instance turns on a true arc between its two steps (Embree slerps
// its rotation): halfway through the shutter the bar lies at 45 degrees at
// full length, where baked vertices would cut the chord (its tip at 0.71).
TEST(RenderScene, ARigidlyMovingInstanceTurnsOnATrueArc) {
  const RenderScene scene(spinningBar(false));
  EXPECT_EQ(scene.stats().embreeInstances, 1);
  EXPECT_EQ(scene.stats().bakedGeometries, 0);
  const float c = std::sqrt(0.5f);
  for (const float r : {0.3f, 0.9f, 0.98f}) {
    const auto hit = scene.intersect(downAt(r * c, r * c, 0.5f));
    ASSERT_TRUE(hit) << r;
    expectVec(hit->position, {r * c, r * c, 0});
    expectVec(hit->geometricNormal, {0, 0, 1});
    // The leaning normal turned by 45 degrees too: (cos 45, sin 45, 1) / sqrt 2.
    expectVec(hit->shadingNormal, {0.5f, 0.5f, c}, 1e-4f);
  }
  EXPECT_FALSE(scene.intersect(downAt(1.02f * c, 1.02f * c, 0.5f)));
  // At the ends of the shutter, the steps themselves.
  EXPECT_TRUE(scene.intersect(downAt(0.95f, 0, 0)));
  EXPECT_FALSE(scene.intersect(downAt(0.95f, 0, 1)));
  EXPECT_TRUE(scene.intersect(downAt(0, 0.95f, 1)));
  // A quarter of the way: 22.5 degrees.
  const float a = 0.3926991f;
  EXPECT_TRUE(scene.intersect(downAt(0.95f * std::cos(a), 0.95f * std::sin(a), 0.25f)));
}

// An emitter is baked at each step instead: the light sampler poses emitters
// linearly between steps, and rays must find them where it does.
TEST(RenderScene, AMovingEmitterIsBakedAtItsTimeSteps) {
  const RenderScene scene(spinningBar(true));
  EXPECT_EQ(scene.stats().embreeInstances, 0);
  EXPECT_EQ(scene.stats().bakedGeometries, 1);
  const float c = std::sqrt(0.5f);
  EXPECT_TRUE(scene.intersect(downAt(0.6f * c, 0.6f * c, 0.5f)));
  EXPECT_FALSE(scene.intersect(downAt(0.9f * c, 0.9f * c, 0.5f)));  // beyond the chord
}

}  // namespace
}  // namespace lensrt
