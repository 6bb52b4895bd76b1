// glTF node animation (scene/gltf_animation.h) against the specification's
// formulas, computed here by hand: a vertex's world position at a time, for
// LINEAR (slerp), STEP and CUBICSPLINE samplers, clamped outside the
// keyframes; the Hermite curve reproduces a cubic exactly; broken channels
// are skipped with a warning naming them.
#include "scene/gltf_animation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <tuple>

#include "core/error.h"
#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

TEST(GltfAnimation, SlerpTurnsAtConstantSpeedTheShortWay) {
  const double h = std::sqrt(0.5);
  // Identity to 90 degrees about z: a quarter of the way is 22.5 degrees.
  const auto q = gltf::slerp({0, 0, 0, 1}, {0, 0, h, h}, 0.25);
  EXPECT_NEAR(q[2], std::sin(std::numbers::pi / 16), 1e-12);
  EXPECT_NEAR(q[3], std::cos(std::numbers::pi / 16), 1e-12);
  // -q is the same rotation: the blend takes the short way, not 270 degrees.
  const auto r = gltf::slerp({0, 0, 0, 1}, {0, 0, -h, -h}, 0.5);
  EXPECT_NEAR(std::abs(r[2]), std::sin(std::numbers::pi / 8), 1e-12);
  EXPECT_NEAR(std::abs(r[3]), std::cos(std::numbers::pi / 8), 1e-12);
}

TEST(GltfAnimation, HermiteReproducesACubic) {
  // f(t) = 2 t^3 - t^2 + 3 t - 1 on [0.5, 2]: values and derivatives at both ends.
  const auto f = [](double t) { return 2 * t * t * t - t * t + 3 * t - 1; };
  const auto df = [](double t) { return 6 * t * t - 2 * t + 3; };
  const double t0 = 0.5, t1 = 2.0;
  for (const double u : {0.0, 0.2, 0.5, 0.9, 1.0})
    EXPECT_NEAR(gltf::hermite(f(t0), df(t0), df(t1), f(t1), t1 - t0, u), f(t0 + u * (t1 - t0)), 1e-12) << u;
}

// A triangle (0,0,0), (1,0,0), (0,1,0) on a node animated by `channels`.
struct Animated {
  GltfBuilder b;
  json samplers = json::array(), channels = json::array();
  int node = 0;
  Animated() {
    const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
    const int mesh = b.mesh({{"attributes", {{"POSITION", pos}}}});
    node = b.node({{"mesh", mesh}});
  }
  void channel(const std::string& path, const std::vector<float>& times, const std::vector<float>& values,
               const std::string& type, const std::string& interpolation) {
    samplers.push_back({{"input", b.floats(times, "SCALAR")},
                        {"output", b.floats(values, type)},
                        {"interpolation", interpolation}});
    channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", path}}}});
  }
  SceneDesc load(double seconds, Warnings& w, const std::string& animation = "") {
    GltfBuilder copy = b;
    copy.doc["animations"] =
        json::array({{{"name", "move"}, {"samplers", samplers}, {"channels", channels}}});
    return loadGltf(test::writeFile(test::testDir() / "anim.gltf", copy.json()), -1, w, {},
                    AnimationTime{seconds, animation});
  }
};

Vec3d worldVertex(const SceneDesc& d, int vertex) {
  const Vec3f p = d.meshes[std::size_t(d.instances.at(0).mesh)].positions.at(std::size_t(vertex));
  return d.instances[0].worldFromObject.point(Vec3d(p.x, p.y, p.z));
}

void expectNear(const Vec3d& a, const Vec3d& b, double tol = 1e-5) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(GltfAnimation, LinearStepAndCubicSplineChannelsPoseTheNode) {
  Animated a;
  // Translation LINEAR from (0,0,0) at t = 1 to (4,0,2) at t = 3.
  a.channel("translation", {1, 3}, {0, 0, 0, 4, 0, 2}, "VEC3", "LINEAR");
  // Rotation STEP: identity until t = 2, then 90 degrees about z.
  const float h = float(std::sqrt(0.5));
  a.channel("rotation", {0, 2}, {0, 0, 0, 1, 0, 0, h, h}, "VEC4", "STEP");
  // Scale CUBICSPLINE from 1 to 3 over [0, 2] with tangents 0 (in, value, out per key).
  a.channel("scale", {0, 2}, {0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0, 3, 3, 3, 0, 0, 0}, "VEC3", "CUBICSPLINE");
  Warnings w;
  // t = 0.5: before the translation's keys (clamped to its first), rotation
  // identity, scale 1 + 2 (3 u^2 - 2 u^3) at u = 0.25.
  const double s = 1 + 2 * (3 * 0.0625 - 2 * 0.015625);
  expectNear(worldVertex(a.load(0.5, w), 1), {s, 0, 0});
  // t = 2.5: translation 3/4 of the way, rotated 90 degrees, scale 3 (after its last key).
  expectNear(worldVertex(a.load(2.5, w), 1), {3 + 0, 3, 1.5});
  // t = 10: every channel at its last key.
  expectNear(worldVertex(a.load(10, w), 2), {4 - 3, 0, 2});
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
}

TEST(GltfAnimation, BrokenChannelsAreSkippedWithAWarningNamingThem) {
  Animated a;
  a.channel("translation", {0, 2, 1}, {0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3", "LINEAR");  // times go back
  a.channel("scale", {0, 1}, {1, 1, 1, 2, 2, 2}, "VEC3", "CUBICSPLINE");               // 2 values, not 6
  a.channel("weights", {0, 1}, {0, 1}, "SCALAR", "LINEAR");  // the mesh has no morph targets
  Warnings w;
  expectNear(worldVertex(a.load(0.5, w), 1), {1, 0, 0});  // at rest
  const std::set<std::string> want = {
      "animation 0 'move' channel 0 (translation) is skipped: its keyframe times do not increase (at "
      "keyframe 2)",
      "animation 0 'move' channel 1 (scale) is skipped: it has 2 output values for 2 keyframes (CUBICSPLINE "
      "needs 3 each)",
      "animation 0 'move' channel 2 (weights) is skipped: its node has no mesh with morph targets"};
  EXPECT_EQ(w.all(), want);
}

TEST(GltfAnimation, AnUnknownAnimationIsAUsageErrorListingTheKnownOnes) {
  Animated a;
  a.channel("translation", {0, 1}, {0, 0, 0, 1, 0, 0}, "VEC3", "LINEAR");
  Warnings w;
  expectNear(worldVertex(a.load(1, w, "move"), 0), {1, 0, 0});
  expectNear(worldVertex(a.load(1, w, "0"), 0), {1, 0, 0});
  try {
    a.load(1, w, "walk");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_EQ(e.option(), "--animation");
    EXPECT_NE(e.message().find("has no animation 'walk' (choose from: 0 'move')"), std::string::npos)
        << e.message();
  }
}

// Morph targets: vertex 1 of the triangle moves by (0, 2, 0) in target 0
// and by (0, 0, 4) in target 1; POSITION = base + sum of weight x delta.
TEST(GltfAnimation, MorphTargetsBlendByTheirWeights) {
  const auto build = [](const json& meshWeights, const json& nodeWeights) {
    Animated a;
    const int t0 = a.b.floats({0, 0, 0, 0, 2, 0, 0, 0, 0}, "VEC3");
    const int t1 = a.b.floats({0, 0, 0, 0, 0, 4, 0, 0, 0}, "VEC3");
    json& mesh = a.b.doc["meshes"][0];
    mesh["primitives"][0]["targets"] = json::array({{{"POSITION", t0}}, {{"POSITION", t1}}});
    if (!meshWeights.is_null()) mesh["weights"] = meshWeights;
    if (!nodeWeights.is_null()) a.b.doc["nodes"][std::size_t(a.node)]["weights"] = nodeWeights;
    return a;
  };
  Warnings w;
  expectNear(worldVertex(build(nullptr, nullptr).load(0, w), 1), {1, 0, 0});
  expectNear(worldVertex(build(json{0.5, 0.25}, nullptr).load(0, w), 1), {1, 1, 1});
  expectNear(worldVertex(build(json{0.5, 0.25}, json{1, 0}).load(0, w), 1), {1, 2, 0});  // the node's win
  // Animated weights: LINEAR from (0, 0) at t = 0 to (1, 0.5) at t = 2, two per keyframe in a SCALAR output.
  Animated a = build(json{0.5, 0.25}, nullptr);
  a.channel("weights", {0, 2}, {0, 0, 1, 0.5}, "SCALAR", "LINEAR");
  expectNear(worldVertex(a.load(1, w), 1), {1, 1, 1});  // (0.5, 0.25)
  expectNear(worldVertex(a.load(5, w), 1), {1, 2, 2});  // clamped at (1, 0.5)
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
  // A count of weights that does not match the targets is an error naming the mesh.
  Warnings w2;
  EXPECT_THROW(build(json{0.5}, nullptr).load(0, w2), InputError);
}

// A skin: vertex 0 follows joint 0 (at the origin), vertex 1 joint 1 (bound
// at (0, 3, 0), then animated to (0, 3, 4) over 2 s), vertex 2 both by half.
// Joint matrices are world x inverse bind: at t = 1 joint 1 has moved by
// (0, 0, 2), so vertex 1 (1, 0, 0) is at (1, 0, 2) and vertex 2 (0, 1, 0) at
// (0, 1, 1); the skinned node's own translation does not apply.
TEST(GltfAnimation, ASkinBlendsVerticesByTheirJoints) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  const int joints = b.u8({0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}, "VEC4");
  const int weights = b.floats({1, 0, 0, 0, 1, 0, 0, 0, 0.5, 0.5, 0, 0}, "VEC4");
  const int mesh =
      b.mesh({{"attributes", {{"POSITION", pos}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}}});
  b.node({{"mesh", mesh}, {"skin", 0}, {"translation", {100, 0, 0}}});
  const int j0 = b.node(json::object());
  const int j1 = b.node({{"translation", {0, 3, 0}}});
  const int bind = b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,   // identity
                             1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -3, 0, 1},  // translate (0, -3, 0)
                            "MAT4");
  b.doc["skins"] = json::array({{{"joints", {j0, j1}}, {"inverseBindMatrices", bind}}});
  b.doc["animations"] = json::array(
      {{{"samplers",
         {{{"input", b.floats({0, 2}, "SCALAR")}, {"output", b.floats({0, 3, 0, 0, 3, 4}, "VEC3")}}}},
        {"channels", {{{"sampler", 0}, {"target", {{"node", j1}, {"path", "translation"}}}}}}}});
  const auto file = test::writeFile(test::testDir() / "skin.gltf", b.json());
  Warnings w;
  for (const auto& [t, v1, v2] :
       {std::tuple{0.0, Vec3d{1, 0, 0}, Vec3d{0, 1, 0}}, std::tuple{1.0, Vec3d{1, 0, 2}, Vec3d{0, 1, 1}}}) {
    const SceneDesc d = loadGltf(file, -1, w, {}, AnimationTime{t, ""});
    expectNear(worldVertex(d, 0), {0, 0, 0});
    expectNear(worldVertex(d, 1), v1);
    expectNear(worldVertex(d, 2), v2);
  }
  EXPECT_TRUE(w.all().empty()) << *w.all().begin();
}

// The Khronos AnimatedTriangle (a LINEAR rotation about z through 0, 90, 180,
// 270 and 360 degrees over one second), kept in tests/assets/khronos (the
// other animated Khronos samples: khronos_animation_test.cpp).
TEST(GltfAnimation, KhronosAnimatedTriangleTurnsAsTheSpecificationSays) {
  const std::filesystem::path file =
      std::filesystem::path(LENSRT_TEST_DATA_DIR) / "assets/khronos/AnimatedTriangle/AnimatedTriangle.gltf";
  ASSERT_TRUE(std::filesystem::exists(file)) << file;
  Warnings w;
  for (const auto& [t, degrees] : {std::pair{0.125, 45.0}, std::pair{0.625, 225.0}, std::pair{0.9, 324.0}}) {
    const SceneDesc d = loadGltf(file, -1, w, {}, AnimationTime{t, ""});
    const double a = degrees * std::numbers::pi / 180;
    expectNear(worldVertex(d, 1), {std::cos(a), std::sin(a), 0});
  }
}

}  // namespace
}  // namespace lensrt
