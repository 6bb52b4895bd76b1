// Light units: a point light of intensity I (W/sr) at height h above a white
// Lambertian plane gives radiance L = I cos(theta) / (pi r^2) at distance r.
#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
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
      // Box filter: the pixel is the mean over its area (8x8 quadrature).
      double expected = 0;
      for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i)
          expected += radiance(planePoint(camera, x + (i + 0.5f) / 8, y + (j + 0.5f) / 8));
      expected /= 64;
      ASSERT_NEAR(img.at(x, y, 0), expected, 0.01 * expected) << "pixel " << x << "," << y;
      ASSERT_NEAR(img.at(x, y, 1), 2 * expected, 0.02 * expected);
      ASSERT_NEAR(img.at(x, y, 2), 0.5 * expected, 0.005 * expected);
    }
}

}  // namespace
}  // namespace lensrt
