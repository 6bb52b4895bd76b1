// glTF's orthographic camera: parallel rays over a view 2 ymag high, objects
// the same size at every distance, and the cases where a lens makes it a
// perspective camera.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "api/camera_factory.h"
#include "camera/camera_test_util.h"
#include "camera/orthographic_camera.h"
#include "camera/pinhole_camera.h"
#include "camera/render_test_util.h"
#include "camera/spec_test_util.h"
#include "camera/thin_lens_camera.h"

namespace lensrt {
namespace {

TEST(Orthographic, ParallelRaysOverTheView) {
  // A camera 5 m up +Z looking down -Z, as glTF places it.
  const OrthographicCamera cam(Transform::translate({0, 0, 5}), test::rasterFilm(200, 100), 1.5);
  EXPECT_DOUBLE_EQ(cam.halfWidth(), 3.0);  // the image's aspect, square pixels
  for (const Vec2f& film : {Vec2f{0, 0}, Vec2f{200, 100}, Vec2f{100, 50}, Vec2f{37.5f, 81.25f}}) {
    const auto r = cam.generateRay(CameraSample{film, {0.5f, 0.5f}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->weight, 1.0f);
    EXPECT_NEAR(r->ray.direction.z, -1.0, 1e-7);
    EXPECT_NEAR(r->ray.origin.x, (film.x / 200.0 * 2 - 1) * 3.0, 1e-6);
    EXPECT_NEAR(r->ray.origin.y, (1 - film.y / 100.0 * 2) * 1.5, 1e-6);
    EXPECT_NEAR(r->ray.origin.z, 5.0, 1e-6);
  }
  EXPECT_EQ(cam.info().model, "orthographic");
  EXPECT_EQ(cam.describe(), "orthographic xmag=3 ymag=1.5 film=radiance");
  EXPECT_THROW(OrthographicCamera(Transform(), test::rasterFilm(8, 8), 0.0), std::invalid_argument);
}

// A 1 m square fills a quarter of a 2 m x 2 m view at 2 m and at 20 m alike
// (a perspective camera would see it 100 times smaller by area at 20 m).
TEST(Orthographic, SizeDoesNotDependOnDistance) {
  const OrthographicCamera cam(Transform(), test::rasterFilm(64, 64), 1.0);
  for (const float distance : {2.0f, 20.0f}) {
    const test::RenderedImage img =
        test::renderScene(test::squareScene(distance, 1.0f, 1.0f), cam, Environment(), 4);
    double sum = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) sum += img.image.at(x, y, img.red);
    EXPECT_NEAR(sum / (64.0 * 64.0), 0.25, 1e-3) << "at " << distance << " m";
  }
}

TEST(Orthographic, ThePinholeModelRendersIt) {
  CameraDesc gltf;
  gltf.name = "top";
  gltf.orthographic = true;
  gltf.xmag = 2;
  gltf.ymag = 1;
  Warnings w;
  test::Flags o;
  const auto cam = test::makeCamera(o, gltf, test::rasterFilm(80, 40), {}, w);
  const auto* ortho = dynamic_cast<const OrthographicCamera*>(cam.get());
  ASSERT_NE(ortho, nullptr);
  EXPECT_DOUBLE_EQ(ortho->halfWidth(), 2.0);
  EXPECT_TRUE(w.all().empty());
  // Another aspect ratio keeps ymag, and says so.
  Warnings square;
  const auto wide = test::makeCamera(o, gltf, test::rasterFilm(40, 40), {}, square);
  EXPECT_DOUBLE_EQ(dynamic_cast<const OrthographicCamera&>(*wide).halfWidth(), 1.0);
  ASSERT_EQ(square.all().size(), 1u);
  EXPECT_NE(square.all().begin()->find("keeping ymag, the view is 2 m wide"), std::string::npos)
      << *square.all().begin();
  // A lens makes a perspective picture.
  Warnings thin;
  test::Flags withLens;
  withLens("--camera", "thin");
  withLens("--focal-length", "50");
  withLens("--fstop", "2");
  withLens("--focus", "3");
  const auto perspective = test::makeCamera(withLens, gltf, test::rasterFilm(80, 40), {}, thin);
  EXPECT_NE(dynamic_cast<const ThinLensCamera*>(perspective.get()), nullptr);
  const std::set<std::string> once{
      "camera 'top' is orthographic; a lens model (thin, thick, lens), --lens, --focal-length or an "
      "irradiance film renders it in perspective"};
  EXPECT_EQ(thin.all(), once);
  // lensrt compare makes its four models with one Warnings: one warning, not four.
  for (const char* model : {"pinhole", "thick", "lens"}) {
    test::Flags other = withLens;
    other("--camera", std::string(model));
    other("--lens", "dgauss-50mm");
    other.spec.camera.focalLengthMm.reset();
    other("--fstop", "2.8");  // within the lens's f/2.03
    test::makeCamera(other, gltf, test::rasterFilm(80, 40), {}, thin);
  }
  EXPECT_EQ(thin.all(), once);
}

}  // namespace
}  // namespace lensrt
