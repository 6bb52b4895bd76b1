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

Material clearGlass(float ior, bool thinWalled) {
  Material m;
  m.name = "glass";
  m.metallic = 0;
  m.roughness = 0;
  m.transmission = 1;
  m.ior = ior;
  m.thickness = thinWalled ? 0.0f : 1.0f;
  return m;
}

// Smooth glass neither absorbs nor emits: under a uniform sky it vanishes,
// solid (refracting, total internal reflection inside) or thin-walled. The
// radiance scaling 1/eta^2 going in and eta^2 coming out must cancel.
TEST(Furnace, GlassSphereVanishes) {
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {40, 40, 36, 24},
                             35 * kPi / 180);
  for (const bool thin : {false, true}) {
    TestRenderSetup setup = furnaceSetup(64, 16);
    setup.pureLambert = false;
    const Image img = test::renderTestScene(
        singleMeshScene(test::makeSphere({0, 0, 0}, 1, 24, 48), clearGlass(1.5f, thin)), camera, setup);
    const auto [mean, n] = coveredMean(img);
    ASSERT_GT(n, 400);
    EXPECT_NEAR(mean, 1.0, 0.01) << (thin ? "thin-walled" : "solid");
  }
}

// A coat or a sheen over a white Lambertian takes from the base what it
// reflects itself: the sphere stays at or below 1 (and loses little).
TEST(Furnace, ClearcoatAndSheenOverWhiteStayAtOrBelowOne) {
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {40, 40, 36, 24},
                             35 * kPi / 180);
  Material coated = test::whiteMatte();
  coated.clearcoat = 1;
  coated.clearcoatRoughness = 0.3f;
  Material sheen = test::whiteMatte();
  sheen.sheenColor = {1, 1, 1};
  sheen.sheenRoughness = 0.5f;
  for (const Material& m : {coated, sheen}) {
    const Image img = test::renderTestScene(singleMeshScene(test::makeSphere({0, 0, 0}, 1, 24, 48), m),
                                            camera, furnaceSetup(9, 32));
    const auto [mean, n] = coveredMean(img);
    ASSERT_GT(n, 400);
    EXPECT_LE(mean, 1.005) << (m.clearcoat > 0 ? "clearcoat" : "sheen");
    EXPECT_GT(mean, 0.9) << (m.clearcoat > 0 ? "clearcoat" : "sheen");
  }
}

// KHR_materials_volume: a slab of thickness d seen at normal incidence under
// the uniform sky. With ior 1 there is no Fresnel: each channel is
// exp(-sigma d) = attenuationColor^(d / attenuationDistance). With ior 1.5,
// R = 0.04 per face and tau = exp(-sigma d), the slab's series of internal
// reflections sums to T = (1 - R)^2 tau / (1 - R^2 tau^2) and
// R_slab = R + (1 - R)^2 R tau^2 / (1 - R^2 tau^2); the sky seen both ways adds them.
TEST(Furnace, AbsorbingSlabFollowsBeerLambert) {
  // A narrow field (2 degrees off axis at most) keeps every ray near normal incidence.
  const PinholeCamera camera(Transform::lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0}), {16, 16, 36, 36},
                             3 * kPi / 180);
  constexpr float kD = 0.5f;
  const Vec3f colour{0.5f, 0.25f, 1.0f};
  for (const float ior : {1.0f, 1.5f}) {
    Material m = clearGlass(ior, false);
    m.attenuationColor = colour;
    m.attenuationDistance = 0.5f;  // = kD: tau is the attenuation colour itself
    TestRenderSetup setup = furnaceSetup(32, 16);
    setup.pureLambert = false;
    const Image img = test::renderTestScene(
        singleMeshScene(test::makeBox({-3, -3, -kD / 2}, {3, 3, kD / 2}), m), camera, setup);
    for (int c = 0; c < 3; ++c) {
      const double tau = colour[std::size_t(c)];
      const double r = std::pow((ior - 1.0) / (ior + 1.0), 2);
      const double denom = 1 - r * r * tau * tau;
      const double expected = (1 - r) * (1 - r) * tau / denom + r + (1 - r) * (1 - r) * r * tau * tau / denom;
      EXPECT_NEAR(test::channelMean(img, std::string(1, "RGB"[c])), expected, 0.005 * expected + 2e-3)
          << "ior " << ior << " channel " << c;
    }
  }
}

}  // namespace
}  // namespace lensrt
