// Render-level checks of the camera models through the whole renderer:
// the thin lens's cos^4 falloff under a uniform sky, and its depth of field
// on the image of a small bright square.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "camera/pinhole_camera.h"
#include "camera/thin_lens_camera.h"
#include "core/constants.h"
#include "render/environment.h"
#include "render_test_util.h"

namespace lensrt {
namespace {

using test::renderScene;
using test::squareScene;

// Under a uniform sky of radiance 1 the normalized thin lens focused at
// infinity records cos^4 of the field angle: compared, pixel by pixel along
// the diagonal, with cos^4 averaged over each pixel's area.
TEST(CameraRender, ThinLensShowsCos4FalloffUnderAUniformSky) {
  const FilmGeometry film{48, 32, 36.0, 24.0};  // 0.75 mm pixels
  ThinLensParams p;
  p.focalLengthMm = 24;  // wide: the corner is 41.9 deg off axis
  p.fNumber = 2.8;
  p.focusMetres = kInfinity;
  const ThinLensCamera cam(Transform(), film, p);
  // The square sits behind the camera: out of view, only the sky is seen.
  SceneDesc desc = squareScene(-5.0f, 0.1f, 0.0f);
  const test::RenderedImage rendered =
      renderScene(std::move(desc), cam, Environment::constant({1, 1, 1}), 16);
  const Image& img = rendered.image;
  const int r = rendered.red;
  for (const auto& [x, y] : {std::pair{24, 16}, std::pair{30, 12}, std::pair{40, 5}, std::pair{47, 0}}) {
    double expected = 0;
    const int n = 64;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double sx = ((x + (i + 0.5) / n) / film.width - 0.5) * film.sensorWidthMm;
        const double sy = (0.5 - (y + (j + 0.5) / n) / film.height) * film.sensorHeightMm;
        const double c2 =
            p.focalLengthMm * p.focalLengthMm / (p.focalLengthMm * p.focalLengthMm + sx * sx + sy * sy);
        expected += c2 * c2;
      }
    expected /= n * n;
    EXPECT_NEAR(img.at(x, y, r), expected, 0.01 * expected) << "pixel " << x << "," << y;
  }
}

// An emissive half-plane (x > 0) at distance d, the lens focused at s: the
// edge blurs by the disk of diameter (f/N) |v_d - v| / v_d, whose line spread
// function has variance (D/4)^2 (plus the pixel's 1/12). And the bright side
// records L (f/v)^2: the bellows factor of the normalized exposure.
TEST(CameraRender, ThinLensBlursAnEdgeByTheBlurDisk) {
  const FilmGeometry film{96, 32, 5.4, 1.8};  // 56.25 um pixels
  const double f = 50, n = 2, s = 2000, d = 1000;
  ThinLensParams p;
  p.focalLengthMm = f;
  p.fNumber = n;
  p.focusMetres = s / 1000;
  const ThinLensCamera cam(Transform(), film, p);
  SceneDesc desc = squareScene(float(d / 1000), 0.4f, 1.0f);
  for (Vec3f& v : desc.meshes[0].positions) v.x = std::max(v.x, 0.0f);  // keep x >= 0: a half-plane
  const std::vector<double> profile =
      test::columnProfile(renderScene(std::move(desc), cam, Environment(), 128));
  double plateau = 0;
  for (int x = film.width - 16; x < film.width; ++x) plateau += profile[x] / 16;
  const double v = f * s / (s - f), vd = f * d / (d - f);
  const double pixel = film.sensorWidthMm / film.width;
  // Bright side: cos^4 is within 0.2% of 1 this close to the axis.
  EXPECT_NEAR(plateau, (f / v) * (f / v), 0.005 * (f / v) * (f / v));
  // Line spread function: the profile's differences, near the edge only
  // (farther out the bright side's gentle cos^4 slope would weigh in).
  double w = 0, m1 = 0, m2 = 0;
  for (int x = film.width / 2 - 14; x <= film.width / 2 + 14; ++x) {
    const double lsf = (profile[x] - profile[x - 1]) / plateau;
    const double at = x * pixel;  // the edge between pixel x-1 and x
    w += lsf;
    m1 += lsf * at;
    m2 += lsf * at * at;
  }
  const double mean = m1 / w, variance = m2 / w - mean * mean;
  const double diameter = 4 * std::sqrt(variance - pixel * pixel / 12);
  const double predicted = (f / n) * std::abs(vd - v) / vd;
  RecordProperty("blur_disk_mm", std::to_string(diameter));
  RecordProperty("predicted_mm", std::to_string(predicted));
  EXPECT_NEAR(diameter, predicted, 0.05 * predicted) << "blur disk diameter in mm";
  EXPECT_NEAR(mean, film.sensorWidthMm / 2, 0.5 * pixel) << "the edge images on the axis";
}

// Closing the aperture turns the thin lens into the pinhole with the field of
// view the lens has at that focus: rendered with the same samples, their
// images of an emissive edge agree (after the bellows factor (f/v)^2 that the
// thin lens records at a finite focus and the pinhole does not), while at f/2
// the out-of-focus edge differs visibly.
TEST(CameraRender, ThinLensWithATinyApertureRendersThePinholeImage) {
  const FilmGeometry film{128, 16, 36.0, 4.5};  // 0.28 mm pixels
  const double f = 50;
  for (const double focusM : {kInfinity, 2.0}) {
    SCOPED_TRACE("focus " + std::to_string(focusM) + " m");
    const double v = std::isinf(focusM) ? f : f * focusM * 1e3 / (focusM * 1e3 - f);
    const double bellows = (f / v) * (f / v);
    const PinholeCamera pinhole(Transform(), film, 2 * std::atan(film.sensorHeightMm / 2 / v), Exposure{},
                                2.0, "");
    const auto render = [&](const Camera& cam) {
      SceneDesc desc = squareScene(1.0f, 2.0f, 1.0f);  // the edge 1 m away, out of focus
      for (Vec3f& p : desc.meshes[0].positions) p.x = std::max(p.x, 0.0f);
      return test::columnProfile(renderScene(std::move(desc), cam, Environment(), 16));
    };
    const std::vector<double> reference = render(pinhole);
    const auto largestDifference = [&](double fNumber) {
      ThinLensParams p;
      p.focalLengthMm = f;
      p.fNumber = fNumber;
      p.focusMetres = focusM;
      const std::vector<double> thin = render(ThinLensCamera(Transform(), film, p));
      double worst = 0;
      for (std::size_t x = 0; x < thin.size(); ++x)
        worst = std::max(worst, std::abs(thin[x] / bellows - reference[x]));
      return worst;
    };
    EXPECT_LT(largestDifference(1000.0), 0.01);
    EXPECT_GT(largestDifference(2.0), 0.1);
  }
}

}  // namespace
}  // namespace lensrt
