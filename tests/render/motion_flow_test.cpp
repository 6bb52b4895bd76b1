// render/motion_flow.h's parts: the surface point a hit follows to another
// moment (a rigid step and a deformed mesh), one sample's flow through a
// pinhole against its closed form, and a pixel's means.
#include "render/motion_flow.h"

#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_camera.h"

namespace lensrt {
namespace {

// One triangle (0,0,0) (1,0,0) (0,1,0); at the span's end the instance has
// moved by (2, 0, -1) and its mesh is the triangle scaled by 2.
SceneDesc movingTriangle() {
  SceneDesc scene;
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.indices = {0, 1, 2};
  Mesh deformed = mesh;
  for (Vec3f& p : deformed.positions) p = p * 2.0f;
  scene.meshes = {mesh, deformed};
  MeshInstance inst;
  inst.mesh = 0;
  inst.worldFromObject = Transform::translate({0, 0, -4});
  inst.motion = {{0, inst.worldFromObject}, {1, Transform::translate({2, 0, -5})}};
  inst.node = 3;
  scene.instances = {inst};
  scene.motionSteps = 2;
  return scene;
}

TEST(MotionFlow, TheSurfacePointFollowsItsTriangleToTheSpansEnd) {
  const SceneDesc scene = movingTriangle();
  const Vec2f b{0.25f, 0.5f};  // the weights of the second and third corner
  const std::optional<Vec3d> open = surfacePointAt(scene, false, 0, 0, b);
  const std::optional<Vec3d> close = surfacePointAt(scene, true, 0, 0, b);
  ASSERT_TRUE(open && close);
  EXPECT_NEAR(open->x, 0.25, 1e-12);
  EXPECT_NEAR(open->y, 0.5, 1e-12);
  EXPECT_NEAR(open->z, -4, 1e-12);
  EXPECT_NEAR(close->x, 2 + 0.5, 1e-12);  // scaled by 2, moved by 2
  EXPECT_NEAR(close->y, 1.0, 1e-12);
  EXPECT_NEAR(close->z, -5, 1e-12);
  EXPECT_FALSE(surfacePointAt(scene, false, 1, 0, b));  // no such instance
  EXPECT_FALSE(surfacePointAt(scene, false, 0, 1, b));  // no such triangle
}

TEST(MotionFlow, ASamplesFlowIsThePinholesClosedForm) {
  const SceneDesc scene = movingTriangle();
  FilmGeometry film;
  film.width = 100;
  film.height = 80;
  const double yfov = 0.6;
  const PinholeCamera camera(Transform(), film, yfov);
  MotionFlow flow;
  flow.overShutter = true;
  flow.next.spanEnd = true;
  // The camera moves +1 in y by the closing: the image moves down by f / z.
  flow.next.cameraFromWorld = Transform::translate({0, -1, 0});
  const Vec2f b{0.25f, 0.5f};
  FlowHints hints;
  const SampleFlow f = sampleFlow(flow, scene, camera, 0, 0, b, hints);
  ASSERT_TRUE(f.forward && f.backward);
  const double focal = 40 / std::tan(yfov / 2);  // pixels
  // x: 0.25 / 4 -> 2.5 / 5; y (up): 0.5 / 4 -> (1 - 1) / 5; raster y is down.
  EXPECT_NEAR(f.forward->x, focal * (2.5 / 5 - 0.25 / 4), 1e-9);
  EXPECT_NEAR(f.forward->y, -focal * (0.0 / 5 - 0.5 / 4), 1e-9);
  EXPECT_EQ(f.backward->x, -f.forward->x);
  EXPECT_EQ(f.backward->y, -f.forward->y);
  // Behind the camera at the closing: no flow in either direction.
  flow.next.cameraFromWorld = Transform::translate({0, 0, 10});
  const SampleFlow behind = sampleFlow(flow, scene, camera, 0, 0, b, hints);
  EXPECT_FALSE(behind.forward || behind.backward);
}

TEST(MotionFlow, APixelWritesEachDirectionsMeanAndZeroWithoutSamples) {
  FlowSums sums;
  float out[4] = {1, 1, 1, 1};
  sums.write(out);
  for (float v : out) EXPECT_EQ(v, 0.0f);
  sums.add({Vec2d{1, 2}, Vec2d{-1, -2}}, 0);
  sums.add({Vec2d{3, 4}, std::nullopt}, 0);
  sums.write(out);
  EXPECT_EQ(out[0], 2.0f);
  EXPECT_EQ(out[1], 3.0f);
  EXPECT_EQ(out[2], -1.0f);  // one backward sample
  EXPECT_EQ(out[3], -2.0f);
}

TEST(MotionFlow, APixelTakesFourSamplesOfOneObjectAndEightOfSeveral) {
  FlowSums one, two;
  for (std::uint32_t i = 0; i < kFlowSamplesPerPixel; ++i) {
    EXPECT_EQ(one.full(), i >= kFlowSamplesOneObject) << i;
    if (!one.full()) one.add({Vec2d{1, 0}, std::nullopt}, 3);
    EXPECT_FALSE(two.full()) << i;
    two.add({Vec2d{1, 0}, std::nullopt}, i == 2 ? 5 : 3);
  }
  EXPECT_TRUE(one.full());
  EXPECT_TRUE(two.full());
  EXPECT_EQ(one.taken, kFlowSamplesOneObject);
  EXPECT_EQ(two.taken, kFlowSamplesPerPixel);
}

}  // namespace
}  // namespace lensrt
