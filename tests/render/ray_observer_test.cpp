// Integrator's RayObserver (the benchmark suite records a pass's rays through
// it): it sees every ray by kind, and watching changes no bit of the image.
#include "render/ray_observer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <mutex>
#include <vector>

#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "render/test_scene_util.h"

namespace lensrt {
namespace {

class Log final : public RayObserver {
 public:
  void traced(RayKind kind, const Ray& ray) override {
    const std::scoped_lock lock(mutex_);
    rays[std::size_t(kind)].push_back(ray);
  }
  std::vector<Ray> rays[3];

 private:
  std::mutex mutex_;
};

SceneDesc unitSphere() {
  SceneDesc s;
  s.sourceFile = "ray observer (in code)";
  Mesh mesh = test::makeSphere({0, 0, 0}, 1, 24, 48);
  mesh.material = 0;
  s.meshes.push_back(std::move(mesh));
  s.materials.push_back(test::whiteMatte());
  s.instances.push_back({0, Transform()});
  return s;
}

// Does the line of a unit-direction ray pass through the unit sphere at the origin, ahead of it?
bool meetsUnitSphere(const Ray& r) {
  const float b = dot(r.origin, r.direction), c = dot(r.origin, r.origin) - 1;
  return b * b - c >= 0 && -b > 0;
}

struct Observed {
  Image image;
  std::vector<Ray> rays[3];
};

Observed render(int maxDepth, bool watch) {
  const PinholeCamera camera(Transform::lookAt({0, 0, 4}, {0, 0, 0}, {0, 1, 0}), {16, 12, 36, 24},
                             40 * kPi / 180);
  test::TestRenderSetup setup;
  setup.environment = Environment::constant({1, 1, 1});
  setup.integrator.maxDepth = maxDepth;
  setup.render.samplesPerPixel = 2;
  setup.render.threads = 2;
  Log log;
  if (watch) setup.integrator.observer = &log;
  Observed out{test::renderTestScene(unitSphere(), camera, setup), {}};
  for (int k = 0; k < 3; ++k) out.rays[k] = log.rays[k];
  return out;
}

TEST(RayObserver, DepthZeroTracesOnlyCameraRaysOnePerSample) {
  const Observed o = render(0, true);
  EXPECT_EQ(o.rays[std::size_t(RayKind::Camera)].size(), 16u * 12u * 2u);
  EXPECT_TRUE(o.rays[std::size_t(RayKind::Bounce)].empty());
  EXPECT_TRUE(o.rays[std::size_t(RayKind::Shadow)].empty());
}

TEST(RayObserver, BounceAndShadowRaysStartOnTheSphereHitByACameraRay) {
  const Observed o = render(1, true);
  const auto& camera = o.rays[std::size_t(RayKind::Camera)];
  const auto& bounce = o.rays[std::size_t(RayKind::Bounce)];
  const auto& shadow = o.rays[std::size_t(RayKind::Shadow)];
  ASSERT_EQ(camera.size(), 16u * 12u * 2u);
  std::size_t meeting = 0;
  for (const Ray& r : camera) meeting += meetsUnitSphere(r);
  // At depth 1 a hit (the tessellated sphere lies inside the unit sphere)
  // makes at most one shadow ray and one bounce ray; a convex object sends
  // every bounce out, so there is nothing more.
  ASSERT_GT(meeting, 20u);
  EXPECT_GT(bounce.size(), 0u);
  EXPECT_GT(shadow.size(), 0u);
  EXPECT_LE(bounce.size(), meeting);
  EXPECT_LE(shadow.size(), meeting);
  for (const auto* rays : {&bounce, &shadow})
    for (const Ray& r : *rays) {
      EXPECT_NEAR(length(r.origin), 1.0f, 0.02f);
      EXPECT_NEAR(length(r.direction), 1.0f, 1e-5f);
      // Outward, up to a facet's tilt from the sphere's normal (7.5 degree facets).
      EXPECT_GT(dot(r.direction, r.origin), -0.2f);
    }
}

TEST(RayObserver, WatchingChangesNoBit) {
  const Observed watched = render(3, true), plain = render(3, false);
  ASSERT_EQ(watched.image.pixels.size(), plain.image.pixels.size());
  for (std::size_t i = 0; i < plain.image.pixels.size(); ++i)
    ASSERT_EQ(watched.image.pixels[i], plain.image.pixels[i]) << "value " << i;
}

}  // namespace
}  // namespace lensrt
