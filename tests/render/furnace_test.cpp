// White furnace: under a uniform environment of radiance 1 a non-absorbing
// surface is invisible, whatever its shape, once paths are long enough.
#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "render/test_scene_util.h"

namespace lensrt {
namespace {

using test::TestRenderSetup;

SceneDesc singleMeshScene(Mesh mesh, Material material) {
  SceneDesc s;
  s.sourceFile = "furnace (in code)";
  mesh.material = 0;
  s.meshes.push_back(std::move(mesh));
  s.materials.push_back(std::move(material));
  s.instances.push_back({0, Transform()});
  return s;
}

TestRenderSetup furnaceSetup(int maxDepth, int spp) {
  TestRenderSetup setup;
  setup.environment = Environment::constant({1, 1, 1});
  setup.integrator.maxDepth = maxDepth;
  setup.render.samplesPerPixel = spp;
  setup.render.seed = 1;
  return setup;
}

// Mean of R over pixels fully covered by geometry (A == 1) and their count.
std::pair<double, int> coveredMean(const Image& img) {
  const int r = img.channelIndex("R"), a = img.channelIndex("A");
  double sum = 0;
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y, a) == 1.0f) {
        sum += img.at(x, y, r);
        ++n;
      }
  return {n ? sum / n : 0.0, n};
}

// A convex object: every path leaves after one bounce, so any depth >= 1 gives 1.
TEST(Furnace, WhiteLambertianSphereVanishesAtEveryDepth) {
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {40, 40, 36, 24},
                             35 * kPi / 180);
  for (int depth = 9; depth <= 16; ++depth) {
    const Image img =
        test::renderTestScene(singleMeshScene(test::makeSphere({0, 0, 0}, 1, 24, 48), test::whiteMatte()),
                              camera, furnaceSetup(depth, 16));
    const auto [mean, n] = coveredMean(img);
    ASSERT_GT(n, 400);
    EXPECT_NEAR(mean, 1.0, 0.01) << "max depth " << depth;
  }
}

// The glTF BRDF with white base colour, metallic 1 and roughness 0 is a
// perfect mirror (Fresnel 1, no masking at alpha -> 0): it vanishes too.
TEST(Furnace, WhiteMirrorSphereVanishes) {
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {40, 40, 36, 24},
                             35 * kPi / 180);
  Material mirror;
  mirror.metallic = 1;
  mirror.roughness = 0;
  TestRenderSetup setup = furnaceSetup(9, 16);
  setup.pureLambert = false;
  const Image img =
      test::renderTestScene(singleMeshScene(test::makeSphere({0, 0, 0}, 1, 24, 48), mirror), camera, setup);
  EXPECT_NEAR(coveredMean(img).first, 1.0, 0.01);
}

// A concave object: a hemispherical bowl seen from straight above. From any
// point inside a sphere, cosine-distributed rays land uniformly over the
// sphere's area, so a diffuse bounce inside the bowl escapes through the opening
// with probability exactly 1/2. With at most D bounces the radiance seen inside
// is therefore 1 - 2^-D: 0.5, 0.75, 0.875 for D = 1, 2, 3 and within 2^-9 of 1
// from D = 9 on.
TEST(Furnace, WhiteBowlLosesExactlyTheEnergyOfTruncatedPaths) {
  const PinholeCamera camera(Transform::lookAt({0, 3, 0}, {0, 0, 0}, {0, 0, -1}), {40, 40, 36, 24},
                             30 * kPi / 180);
  const Mesh bowl = test::makeSphere({0, 0, 0}, 1, 24, 64, float(kPi / 2));
  for (int depth : {1, 2, 3, 9, 12, 16}) {
    const Image img = test::renderTestScene(singleMeshScene(bowl, test::whiteMatte(true)), camera,
                                            furnaceSetup(depth, depth <= 3 ? 64 : 16));
    const auto [mean, n] = coveredMean(img);
    ASSERT_GT(n, 400);
    const double expected = 1.0 - std::pow(0.5, depth);
    // 1% for noise and for the faceted bowl not being exactly spherical.
    EXPECT_NEAR(mean, expected, 0.01) << "max depth " << depth;
  }
}

}  // namespace
}  // namespace lensrt
