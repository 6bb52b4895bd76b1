// The four models agree on orientation: the axis is -Z, the picture is
// upright (camera +Y at the top of the raster, +X at the right), and the
// camera's transform places the rays in the world.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "camera/lens_camera.h"
#include "camera/pinhole_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/paraxial.h"
#include "optics/sample_sequence.h"

namespace lensrt {
namespace {

// The four models derived from one lens, as `lensrt render --lens` builds them.
std::vector<std::unique_ptr<Camera>> allModels(const Transform& t, double focusM) {
  const FilmGeometry film = test::testFilm();
  const LensPrescription lens = test::lectureDoubleGauss(0.5);
  const ParaxialData p = computeParaxial(lens);
  std::vector<std::unique_ptr<Camera>> cams;
  cams.push_back(std::make_unique<PinholeCamera>(t, film, lensVerticalFov(p, focusM, film.sensorHeightMm),
                                                 Exposure{}, 4.0));
  ThinLensParams thin;
  thin.focalLengthMm = p.efl;
  thin.fNumber = 4;
  thin.focusMetres = focusM;
  cams.push_back(std::make_unique<ThinLensCamera>(t, film, thin));
  cams.push_back(std::make_unique<ThickLensCamera>(t, film, thickLensFromParaxial(p, 4, focusM)));
  Warnings warnings;
  LensCameraParams lp;
  lp.fNumber = 4;
  lp.focusMetres = focusM;
  cams.push_back(std::make_unique<LensCamera>(t, film, lens, lp, Exposure{}, warnings));
  return cams;
}

// Where a camera-space point images through the middle of the aperture
// (the full lens: through the centre of its rear vertex plane).
std::optional<Vec2d> chiefImage(const Camera& cam, const Vec3d& p) {
  if (const auto* lens = dynamic_cast<const LensCamera*>(&cam)) {
    return test::imageOf(
        [&](Vec2d raster) {
          return lens->traceThrough({float(raster.x), float(raster.y)}, {0, 0});
        },
        p, {320, 180});
  }
  return test::imageOf(cam, p, {0.5, 0.5}, {320, 180});
}

TEST(Orientation, CentreRayOfEveryModelLooksDownMinusZ) {
  for (const auto& cam : allModels(Transform(), kInfinity)) {
    // Focused at infinity, every ray from the film centre is parallel to the axis.
    SplitMix64 rng(8);
    int passed = 0;
    for (int i = 0; i < 50; ++i) {
      const auto r = test::cameraRay(*cam, {320, 180}, {rng.uniform(), rng.uniform()});
      if (!r) continue;  // the full lens's pupil bounds are conservative
      ++passed;
      EXPECT_NEAR(r->direction.z, -1.0, 1e-6) << cam->describe();
    }
    EXPECT_GT(passed, 20) << cam->describe();
  }
}

TEST(Orientation, PictureIsUprightInEveryModelAndPlacedByTheTransform) {
  // Looking along world +X from (1, 2, 3), +Y up: camera +X is world +Z.
  const Transform t = Transform::lookAt({1, 2, 3}, {5, 2, 3}, {0, 1, 0});
  for (const auto& cam : allModels(t, 3.0)) {
    std::optional<Ray> centre;
    for (double u = 0.5; !centre && u < 0.9; u += 0.01) centre = test::cameraRay(*cam, {320, 180}, {u, 0.5});
    ASSERT_TRUE(centre);
    EXPECT_GT(centre->direction.x, 0.999) << cam->describe();
    const auto img = chiefImage(*cam, {0.3, 0.2, -3.0});
    ASSERT_TRUE(img) << cam->describe();
    EXPECT_GT(img->x, 330) << cam->describe() << ": camera +X must be on the right";
    EXPECT_LT(img->y, 170) << cam->describe() << ": camera +Y must be at the top";
  }
}

// The same scene point lands at nearly the same pixel in every model derived
// from one lens (they differ by the lens's distortion and the thin lens's
// missing thickness): the models share the raster convention and scale.
TEST(Orientation, ModelsAgreeOnWhereAPointImages) {
  const auto cams = allModels(Transform(), 3.0);
  const Vec3d p{-0.25, 0.15, -3.0};
  std::vector<Vec2d> images;
  for (const auto& cam : cams) {
    const auto img = chiefImage(*cam, p);
    ASSERT_TRUE(img) << cam->describe();
    images.push_back(*img);
  }
  for (std::size_t i = 0; i < images.size(); ++i) {
    EXPECT_NEAR(images[i].x, images[2].x, 1.5) << cams[i]->describe();
    EXPECT_NEAR(images[i].y, images[2].y, 1.5) << cams[i]->describe();
  }
  EXPECT_LT(images[2].x, 320);
  EXPECT_LT(images[2].y, 180);
}

}  // namespace
}  // namespace lensrt
