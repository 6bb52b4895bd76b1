// Film statistics, determinism of the tiled renderer, area-light radiometry
// (NEE and BSDF sampling combined by MIS) and the AOVs against closed forms.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "render/lights.h"
#include "render/test_scene_util.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

TEST(Film, VarianceIsTheVarianceOfThePixelMean) {
  PixelAccumulator acc;
  for (float v : {1.0f, 2.0f, 3.0f, 4.0f}) {
    PathSample s;
    s.radiance = {v, 2 * v, 0};
    acc.add(s, 1.0f);
  }
  PathSample bad;
  bad.radiance = {std::nanf(""), 0, 0};
  acc.add(bad, 1.0f);  // dropped and counted, not averaged
  AovSelection aovs;
  aovs.variance = true;
  float out[7];
  acc.write(aovs, out);
  EXPECT_EQ(acc.droppedSamples(), 1u);
  EXPECT_FLOAT_EQ(out[0], 2.5f);
  // Sample variance of 1..4 is 5/3; over n = 4 samples: 5/12.
  EXPECT_FLOAT_EQ(out[4], 5.0f / 12.0f);
  EXPECT_FLOAT_EQ(out[5], 4 * 5.0f / 12.0f);
  EXPECT_FLOAT_EQ(out[6], 0.0f);
}

SceneDesc sphereOnPlane() {
  SceneDesc s;
  s.sourceFile = "sphere on plane (in code)";
  s.meshes.push_back(test::makeSphere({0, 1, 0}, 1, 16, 32));
  s.meshes.push_back(test::makeQuadY(0, 20));
  s.meshes.push_back(test::makeRectFacingDown(-1, 1, -1, 1, 4));
  for (int i = 0; i < 3; ++i) {
    s.meshes[i].material = i;
    s.instances.push_back({i, Transform()});
  }
  Material glossy;
  glossy.baseColor = {0.9f, 0.5f, 0.2f, 1};
  glossy.metallic = 0.5f;
  glossy.roughness = 0.4f;
  s.materials = {glossy, test::whiteMatte(), test::whiteMatte()};
  s.materials[2].emissive = {5, 5, 5};
  return s;
}

TEST(Renderer, ImageIsIdenticalForAnyThreadCountAndTiling) {
  const PinholeCamera camera(Transform::lookAt({0, 2, 5}, {0, 1, 0}, {0, 1, 0}), {37, 23, 36, 24}, 0.8);
  test::TestRenderSetup setup;
  setup.environment = Environment::constant({0.1f, 0.2f, 0.3f});
  setup.pureLambert = false;
  setup.render.samplesPerPixel = 4;
  setup.render.aovs = {true, true, true, true};
  setup.render.threads = 1;
  setup.render.tileSize = 16;
  const Image a = test::renderTestScene(sphereOnPlane(), camera, setup);
  setup.render.threads = 2;
  setup.render.tileSize = 5;
  const Image b = test::renderTestScene(sphereOnPlane(), camera, setup);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
  setup.render.seed = 1;
  const Image c = test::renderTestScene(sphereOnPlane(), camera, setup);
  EXPECT_NE(std::memcmp(a.pixels.data(), c.pixels.data(), a.pixels.size() * sizeof(float)), 0);
}

// Irradiance at a point below the corner of a parallel a x b rectangle of
// radiance L at height h (the classic form-factor result), over L.
double cornerIrradiance(double a, double b, double h) {
  const double ra = std::sqrt(a * a + h * h), rb = std::sqrt(b * b + h * h);
  return 0.5 * (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb));
}

// A scene under a black sky, traced ray by ray, its material 0 (the plane)
// made exactly Lambertian.
struct BlackSkyTracer {
  static MaterialTable lambertFirst(const SceneDesc& desc) {
    MaterialTable m(desc);
    m.extra(0).specularWeight = 0;
    return m;
  }
  static IntegratorSettings depth(int maxDepth) {
    IntegratorSettings s;
    s.maxDepth = maxDepth;
    return s;
  }
  BlackSkyTracer(SceneDesc desc, int maxDepth)
      : scene(std::move(desc)),
        materials(lambertFirst(scene.desc())),
        lights(materials, black, scene.bounds()),
        integrator(scene, materials, lights, black, depth(maxDepth)) {}
  RenderScene scene;
  MaterialTable materials;
  Environment black;
  LightSet lights;
  Integrator integrator;
};

TEST(Renderer, AreaLightOverLambertianPlaneMatchesTheFormFactor) {
  // A 2 x 1 m emitter of radiance 3 at height 1.5 over a white Lambertian plane.
  constexpr double kL = 3, kH = 1.5, kX0 = -1.2, kX1 = 0.8, kZ0 = -0.4, kZ1 = 0.6;
  SceneDesc s;
  s.sourceFile = "area light (in code)";
  s.meshes.push_back(test::makeQuadY(0, 40));
  s.meshes.push_back(test::makeRectFacingDown(float(kX0), float(kX1), float(kZ0), float(kZ1), float(kH)));
  s.meshes[0].material = 0;
  s.meshes[1].material = 1;
  s.instances = {{0, Transform()}, {1, Transform()}};
  s.materials = {test::whiteMatte(), test::whiteMatte()};
  s.materials[1].baseColor = {0, 0, 0, 1};
  s.materials[1].emissive = {float(kL), float(kL), float(kL)};

  const BlackSkyTracer tracer(std::move(s), 1);
  const Integrator& integrator = tracer.integrator;

  // Points on the plane under the light; superpose four corner rectangles.
  for (const Vec3f target : {Vec3f{0, 0, 0}, Vec3f{0.5f, 0, 0.3f}, Vec3f{1.5f, 0, -1}}) {
    const double dx0 = kX0 - target.x, dx1 = kX1 - target.x, dz0 = kZ0 - target.z, dz1 = kZ1 - target.z;
    const auto signedCorner = [&](double a, double b) {
      return (a < 0 ? -1 : 1) * (b < 0 ? -1 : 1) * cornerIrradiance(std::abs(a), std::abs(b), kH);
    };
    const double e = kL * (signedCorner(dx1, dz1) - signedCorner(dx0, dz1) - signedCorner(dx1, dz0) +
                           signedCorner(dx0, dz0));
    const double expected = e / kPi;  // white Lambertian: L = E / pi

    // A ray from a point between plane and light, aimed obliquely at the target.
    const Vec3f origin = target + Vec3f{0.3f, 0.5f, 0.2f};
    const Ray ray{origin, normalize(target - origin), 0, kInfinityF};
    double sum = 0;
    constexpr int kN = 4096;
    for (int i = 0; i < kN; ++i) sum += integrator.trace(ray, Sampler(5, 0, std::uint32_t(i))).radiance.y;
    EXPECT_NEAR(sum / kN, expected, 0.01 * expected) << "target " << target.x << "," << target.z;
  }
}

// The same plane and light with a thin-walled glass sheet of ior 1 between
// them: it transmits everything straight through, so the closed form still
// holds, but shadow rays stop at the sheet and the light is reached only by
// BSDF sampling through it (no leak, nothing counted twice).
TEST(Renderer, LightThroughAnIndexMatchedSheetKeepsTheFormFactor) {
  constexpr double kL = 3, kH = 1.5;
  SceneDesc s;
  s.sourceFile = "area light behind glass (in code)";
  s.meshes.push_back(test::makeQuadY(0, 40));
  s.meshes.push_back(test::makeRectFacingDown(-1, 1, -1, 1, float(kH)));
  s.meshes.push_back(test::makeQuadY(1.0f, 40));
  for (int i = 0; i < 3; ++i) {
    s.meshes[i].material = i;
    s.instances.push_back({i, Transform()});
  }
  s.materials = {test::whiteMatte(), test::whiteMatte(), test::whiteMatte(true)};
  s.materials[1].baseColor = {0, 0, 0, 1};
  s.materials[1].emissive = {float(kL), float(kL), float(kL)};
  s.materials[2].transmission = 1;
  s.materials[2].ior = 1;
  s.materials[2].roughness = 0;

  const BlackSkyTracer tracer(std::move(s), 2);  // plane, sheet, light
  const Integrator& integrator = tracer.integrator;
  const double expected = kL * 4 * cornerIrradiance(1, 1, kH) / kPi;  // under the centre
  const Vec3f origin{0.3f, 0.5f, 0.2f};
  const Ray ray{origin, normalize(Vec3f{0, 0, 0} - origin), 0, kInfinityF};
  double sum = 0;
  constexpr int kN = 65536;
  for (int i = 0; i < kN; ++i) sum += integrator.trace(ray, Sampler(5, 0, std::uint32_t(i))).radiance.y;
  EXPECT_NEAR(sum / kN, expected, 0.02 * expected);
}

TEST(Renderer, AovsReportTheFirstHit) {
  // Camera on +Z looking at a unit sphere 4 m away: the centre pixel sees the
  // pole at distance 3 with normal +Z; corners see the background.
  SceneDesc s;
  s.meshes.push_back(test::makeSphere({0, 0, 0}, 1, 48, 96));
  s.meshes[0].material = 0;
  s.instances.push_back({0, Transform()});
  Material m;
  m.baseColor = {0.2f, 0.4f, 0.6f, 1};
  s.materials.push_back(m);
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {21, 21, 36, 36}, 0.7);
  test::TestRenderSetup setup;
  setup.render.samplesPerPixel = 4;
  setup.render.aovs = {true, true, true, false};
  const Image img = test::renderTestScene(s, camera, setup);
  const auto at = [&](int x, int y, const char* c) { return img.at(x, y, img.channelIndex(c)); };
  EXPECT_NEAR(at(10, 10, "depth.Z"), 3.0f, 0.01f);
  EXPECT_NEAR(at(10, 10, "normal.Z"), 1.0f, 0.01f);
  EXPECT_NEAR(at(10, 10, "albedo.G"), 0.4f, 1e-5f);
  EXPECT_EQ(at(10, 10, "A"), 1.0f);
  EXPECT_EQ(at(0, 0, "A"), 0.0f);
  EXPECT_EQ(at(0, 0, "depth.Z"), 0.0f);
  EXPECT_EQ(at(0, 0, "albedo.R"), 0.0f);
}

}  // namespace
}  // namespace lensrt
