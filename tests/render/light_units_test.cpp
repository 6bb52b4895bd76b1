// Light units: a point light of intensity I (W/sr) at height h above a white
// Lambertian plane gives radiance L = I cos(theta) / (pi r^2) at distance r.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "render/dielectric_bsdf.h"
#include "render/test_scene_util.h"

namespace lensrt {
namespace {

SceneDesc planeScene() {
  SceneDesc s;
  s.sourceFile = "plane (in code)";
  Mesh plane = test::makeQuadY(0, 40);
  plane.material = 0;
  s.meshes.push_back(plane);
  s.materials.push_back(test::whiteMatte());
  s.instances.push_back({0, Transform()});
  return s;
}

// Plane point seen through film position (x, y) of the camera.
Vec3f planePoint(const Camera& camera, float x, float y) {
  const Ray r = camera.generateRay({{x, y}, {0.5f, 0.5f}, 550})->ray;
  return r.origin + r.direction * (-r.origin.y / r.direction.y);
}

// The pixel (x, y) of a box filter: the mean of `radiance` over the plane
// points the pixel sees (8x8 quadrature).
double boxFiltered(const Camera& camera, int x, int y, const std::function<double(const Vec3f&)>& radiance) {
  double sum = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) sum += radiance(planePoint(camera, x + (i + 0.5f) / 8, y + (j + 0.5f) / 8));
  return sum / 64;
}

TEST(LightUnits, PointLightOverLambertianPlane) {
  constexpr float kIntensity = 7.0f, kHeight = 1.5f;
  SceneDesc scene = planeScene();
  PunctualLight light;
  light.type = PunctualLight::Type::Point;
  light.intensity = {kIntensity, 2 * kIntensity, 0.5f * kIntensity};
  light.position = {0.3f, kHeight, -0.2f};
  scene.lights.push_back(light);

  const PinholeCamera camera(Transform::lookAt({1, 4, 1}, {0.3f, 0, -0.2f}, {0, 1, 0}), {32, 32, 36, 24},
                             50 * kPi / 180);
  test::TestRenderSetup setup;
  setup.integrator.maxDepth = 1;
  setup.render.samplesPerPixel = 16;
  const Image img = test::renderTestScene(scene, camera, setup);

  const auto radiance = [&](const Vec3f& p) {
    const Vec3f d = light.position - p;
    const double r2 = lengthSquared(d), cosTheta = d.y / std::sqrt(r2);
    return kIntensity * cosTheta / (kPi * r2);
  };
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double expected = boxFiltered(camera, x, y, radiance);
      ASSERT_NEAR(img.at(x, y, 0), expected, 0.01 * expected) << "pixel " << x << "," << y;
      ASSERT_NEAR(img.at(x, y, 1), 2 * expected, 0.02 * expected);
      ASSERT_NEAR(img.at(x, y, 2), 0.5 * expected, 0.005 * expected);
    }
}

// The same light behind a smooth thin-walled glass pane (ior 1.5, tinted
// 1, 0.5, 1) between it and the plane: the pane passes (1 - F) of it, F the
// Fresnel reflectance at the angle the light crosses it (the pane and the
// plane are parallel, so that of the plane's cosine). Shadow rays toward
// punctual lights cross smooth thin glass; nothing else could carry this light.
TEST(LightUnits, PointLightThroughAThinGlassPane) {
  constexpr float kIntensity = 7.0f, kHeight = 1.5f;
  SceneDesc scene = planeScene();
  Mesh pane = test::makeQuadY(1.0f, 40);
  pane.material = 1;
  scene.meshes.push_back(pane);
  scene.instances.push_back({1, Transform()});
  Material glass;
  glass.baseColor = {1, 0.5f, 1, 1};
  glass.metallic = 0;
  glass.roughness = 0;
  glass.transmission = 1;
  glass.doubleSided = true;
  scene.materials.push_back(glass);
  PunctualLight light;
  light.intensity = {kIntensity, kIntensity, kIntensity};
  light.position = {0.3f, kHeight, -0.2f};
  scene.lights.push_back(light);

  // Below the pane, looking down at the plane.
  const PinholeCamera camera(Transform::lookAt({0.8f, 0.9f, 0.6f}, {0.3f, 0, -0.2f}, {0, 1, 0}),
                             {24, 24, 36, 24}, 50 * kPi / 180);
  test::TestRenderSetup setup;
  setup.integrator.maxDepth = 1;
  setup.render.samplesPerPixel = 16;
  setup.pureLambert = false;        // the pane keeps its Fresnel reflection,
  scene.materials[0].specular = 0;  // the plane is Lambertian through KHR_materials_specular
  const Image img = test::renderTestScene(scene, camera, setup);

  const auto radiance = [&](const Vec3f& p) {
    const Vec3f d = light.position - p;
    const double r2 = lengthSquared(d), cosTheta = d.y / std::sqrt(r2);
    return kIntensity * cosTheta / (kPi * r2) * (1 - fresnelDielectric(float(cosTheta), 1.5f));
  };
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double expected = boxFiltered(camera, x, y, radiance);
      ASSERT_NEAR(img.at(x, y, 0), expected, 0.01 * expected) << "pixel " << x << "," << y;
      ASSERT_NEAR(img.at(x, y, 1), 0.5 * expected, 0.005 * expected) << "pixel " << x << "," << y;
    }
  // A rough pane (roughness 0.5) stops these shadow rays: its light arrives
  // only by scattering at the pane, which needs a second bounce.
  scene.materials[1].roughness = 0.5f;
  const Image rough = test::renderTestScene(scene, camera, setup);
  EXPECT_EQ(test::channelMean(rough, "R"), 0.0);
}

}  // namespace
}  // namespace lensrt
