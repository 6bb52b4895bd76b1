#include "scene/camera_selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.h"
#include "core/error.h"
#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"
#include "scene/selection_error.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

// Root 0: a mesh; root 1: group with child camera "Side"; root 2: camera "Main".
// Traversal is depth-first in file order, so "Side" comes first.
SceneDesc twoCameras() {
  GltfBuilder b;
  b.doc["cameras"] = {
      {{"type", "perspective"},
       {"name", "maincam"},
       {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.5}, {"znear", 0.1}}}},
      {{"type", "perspective"}, {"name", "sidecam"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.2}}}}};
  b.node({{"mesh", b.square()}});
  const int side =
      b.node({{"name", "Side"}, {"camera", 1}, {"translation", {5, 0, 0}}, {"scale", {3, 3, 3}}}, false);
  b.node({{"children", {side}}});
  b.node({{"name", "Main"}, {"camera", 0}, {"translation", {0, 1, 5}}});
  Warnings w;
  return loadGltf(test::writeFile(test::testDir() / "cams.gltf", b.json()), -1, w);
}

TEST(CameraSelection, CamerasInTraversalOrderWithTheirParameters) {
  const SceneDesc d = twoCameras();
  ASSERT_EQ(d.cameras.size(), 2u);
  EXPECT_EQ(d.cameras[0].name, "Side");
  EXPECT_EQ(d.cameras[0].node, 1);
  const CameraDesc& main = d.cameras[1];
  EXPECT_EQ(main.name, "Main");
  EXPECT_EQ(main.cameraName, "maincam");
  EXPECT_FLOAT_EQ(main.yfov, 0.8f);
  ASSERT_TRUE(main.aspectRatio);
  EXPECT_FLOAT_EQ(*main.aspectRatio, 1.5f);
  EXPECT_FLOAT_EQ(main.znear, 0.1f);
  EXPECT_FALSE(d.cameras[0].aspectRatio);
  const Vec3d eye = main.worldFromCamera.point(Vec3d(0, 0, 0));
  EXPECT_NEAR(eye.y, 1, 1e-12);
  EXPECT_NEAR(eye.z, 5, 1e-12);
  // The node's scale of 3 is dropped: camera axes stay unit length.
  EXPECT_NEAR(length(d.cameras[0].worldFromCamera.vector(Vec3d(0, 0, -1))), 1.0, 1e-12);
  EXPECT_NEAR(d.cameras[0].worldFromCamera.point(Vec3d(0, 0, 0)).x, 5, 1e-12);
}

TEST(CameraSelection, ByDefaultNameCameraNameAndNodeIndex) {
  const SceneDesc d = twoCameras();
  EXPECT_EQ(selectCamera(d, "", 1.0f).name, "Side");
  EXPECT_EQ(selectCamera(d, "Main", 1.0f).name, "Main");
  EXPECT_EQ(selectCamera(d, "maincam", 1.0f).name, "Main");
  EXPECT_EQ(selectCamera(d, "3", 1.0f).name, "Main");
  EXPECT_EQ(selectCamera(d, "1", 1.0f).name, "Side");
}

TEST(CameraSelection, UnknownSelectorListsTheCameras) {
  const SceneDesc d = twoCameras();
  try {
    selectCamera(d, "Top", 1.0f);
    FAIL();
  } catch (const SelectionError& e) {  // the request is wrong, not the file: a usage error
    EXPECT_EQ(e.message(), "no camera named 'Top' (cameras: 1 'Side', 3 'Main')");
  }
  try {
    selectCamera(d, "0", 1.0f);
    FAIL();
  } catch (const SelectionError& e) {
    EXPECT_EQ(e.message(), "node 0 is not a camera node (cameras: 1 'Side', 3 'Main')");
  }
}

// Camera-space position of a world point.
Vec3d toCamera(const CameraDesc& c, const Vec3d& p) {
  return c.worldFromCamera.inverse().point(p);
}

void expectFramed(const Bounds3f& box, float aspect) {
  const CameraDesc cam = frameBounds(box, aspect);
  const Vec3d centre(box.center());
  const double radius = 0.5 * length(Vec3d(box.diagonal()));
  const double halfV = 20.0 * kPi / 180.0;
  const double halfH = std::atan(aspect * std::tan(halfV));
  EXPECT_NEAR(cam.yfov, 2 * halfV, 1e-6);
  // The bounding sphere touches the tighter side of the frustum: d = r / sin(half angle).
  const Vec3d eye = cam.worldFromCamera.point(Vec3d(0, 0, 0));
  EXPECT_NEAR(length(eye - centre), radius / std::sin(std::min(halfV, halfH)), 1e-4 * radius);
  // Looking at the centre, from +Z, raised 15 degrees.
  const Vec3d c = toCamera(cam, centre);
  EXPECT_NEAR(c.x, 0, 1e-9 * radius);
  EXPECT_NEAR(c.y, 0, 1e-9 * radius);
  EXPECT_LT(c.z, 0);
  EXPECT_NEAR(std::asin((eye.y - centre.y) / length(eye - centre)), 15 * kPi / 180, 1e-9);
  EXPECT_GT(eye.z, centre.z);
  // Every corner inside the frustum.
  for (int k = 0; k < 8; ++k) {
    const Vec3d p{(k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                  (k & 4) ? box.hi.z : box.lo.z};
    const Vec3d q = toCamera(cam, p);
    ASSERT_LT(q.z, -cam.znear);
    EXPECT_LE(std::abs(q.y / q.z), std::tan(halfV) + 1e-9);
    EXPECT_LE(std::abs(q.x / q.z), aspect * std::tan(halfV) + 1e-9);
  }
}

TEST(CameraSelection, DefaultViewFramesTheBoundingSphere) {
  Bounds3f box;
  box.extend(Vec3f{-1, 2, -3});
  box.extend(Vec3f{3, 4, 1});
  expectFramed(box, 1.5f);  // landscape: vertical fov limits
  expectFramed(box, 0.5f);  // portrait: horizontal fov limits
}

TEST(CameraSelection, NoCameraFallsBackToDefaultView) {
  SceneDesc d;
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  d.meshes.push_back(m);
  d.instances.push_back({0, Transform()});
  const CameraDesc cam = selectCamera(d, "", 1.0f);
  EXPECT_EQ(cam.name, "default view");
  EXPECT_EQ(cam.node, -1);
  const Vec3d c = toCamera(cam, Vec3d(0.5, 0.5, 0));
  EXPECT_NEAR(c.x, 0, 1e-9);
  EXPECT_NEAR(c.y, 0, 1e-9);
}

}  // namespace
}  // namespace lensrt
