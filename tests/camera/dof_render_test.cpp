// Depth of field of the thin lens measured in renders: the blur circle of a
// small emitter at many distances against the geometric prediction, and the
// distances where it equals the circle of confusion against the seed's D_N
// and D_F.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "camera/thin_lens_camera.h"
#include "render/environment.h"
#include "render_test_util.h"

namespace lensrt {
namespace {

// Second moments of the rendered spot about its centroid, in mm^2 on the film
// (pixel centres, upright sensor coordinates: the spot is round, so the
// orientation does not matter).
double spotSecondMoment(const test::RenderedImage& img, double pixelMm) {
  double w = 0, mx = 0, my = 0, mr = 0;
  for (int y = 0; y < img.image.height; ++y)
    for (int x = 0; x < img.image.width; ++x) {
      const double v = img.image.at(x, y, img.red);
      const double px = (x + 0.5) * pixelMm, py = (y + 0.5) * pixelMm;
      w += v;
      mx += v * px;
      my += v * py;
      mr += v * (px * px + py * py);
    }
  mx /= w;
  my /= w;
  return mr / w - mx * mx - my * my;
}

// Where the blur, sampled at distances `d` (ascending), crosses `c` between
// samples i and i + 1, interpolated linearly in log distance.
double crossing(const std::vector<double>& d, const std::vector<double>& b, std::size_t i, double c) {
  const double t = (c - b[i]) / (b[i + 1] - b[i]);
  return std::exp(std::log(d[i]) + t * (std::log(d[i + 1]) - std::log(d[i])));
}

// The image of a small square emitter at distance d through a thin lens
// focused at s is the square's geometric image (side a v / d, through the
// lens centre) convolved with the blur disk of diameter
// b = (f/N) |v_d - v| / v_d; the box pixel adds its own spread. Second
// moments add under convolution: E[r^2] = b^2/8 (a uniform disk, R^2/2) +
// 2 (a v/d)^2/12 + 2 p^2/12, which gives b from the render. With
// f = 50 mm, N = 4, s = 2 m and c = 0.16 mm, N c (s - f) / f^2 = 1/2, so
// D_N = 2s/3 and D_F = 2s: both finite, and the blur at each is c = 10 pixels.
TEST(DofRender, ThinLensBlurCircleAndDepthOfFieldLimitsMatchTheSeed) {
  const double f = 50, n = 4, s = 2000, c = 0.16, pixel = 0.016;
  const int size = 48;  // 0.77 mm of film: the widest spot (0.55 s) is 21 pixels across
  const FilmGeometry film{size, size, size * pixel, size * pixel};
  ThinLensParams p;
  p.focalLengthMm = f;
  p.fNumber = n;
  p.focusMetres = s / 1000;
  const ThinLensCamera cam(Transform(), film, p);
  const double v = cam.imageDistanceMm();
  // The emitter's image is kept at half the circle of confusion at every
  // distance: large enough that most camera rays through the spot find it.
  const double sourceImage = 0.5 * c;

  std::vector<double> distances, measured;
  const int count = 18;
  for (int i = 0; i < count; ++i) {
    const double d = s * 0.55 * std::pow(2.8 / 0.55, double(i) / (count - 1));
    const double side = sourceImage * d / v;  // mm
    const test::RenderedImage img = test::renderScene(
        test::squareScene(float(d / 1000), float(side / 1000), 100.0f), cam, Environment(), 128);
    const double disk = spotSecondMoment(img, pixel) - (sourceImage * sourceImage + pixel * pixel) / 6;
    const double b = std::sqrt(8 * std::max(disk, 0.0));
    const double vd = f * d / (d - f);
    const double predicted = (f / n) * std::abs(vd - v) / vd;
    std::printf("d = %7.1f mm: blur %.4f mm, predicted %.4f mm\n", d, b, predicted);
    // Within 3% where the disk spans 4 pixels or more. A smaller one is a
    // small remainder of the source's and the pixel's spread, and the pixel's
    // own part of the sampled second moment depends on where a sharp spot's
    // edges fall within the pixels (by up to p^2/6): the moment cannot
    // resolve it.
    if (predicted >= 4 * pixel) {
      EXPECT_NEAR(b, predicted, 0.03 * predicted) << "blur diameter at d = " << d << " mm";
    }
    distances.push_back(d);
    measured.push_back(b);
  }

  const double x = n * c * (s - f);
  const double nearLimit = s * f * f / (f * f + x), farLimit = s * f * f / (f * f - x);
  double nearMeasured = 0, farMeasured = 0;
  for (std::size_t i = 0; i + 1 < distances.size(); ++i) {
    if (measured[i] >= c && measured[i + 1] < c) nearMeasured = crossing(distances, measured, i, c);
    if (measured[i] < c && measured[i + 1] >= c) farMeasured = crossing(distances, measured, i, c);
  }
  RecordProperty("near_limit_mm", std::to_string(nearMeasured));
  RecordProperty("far_limit_mm", std::to_string(farMeasured));
  std::printf("D_N measured %.1f mm, seed %.1f mm; D_F measured %.1f mm, seed %.1f mm\n", nearMeasured,
              nearLimit, farMeasured, farLimit);
  EXPECT_NEAR(nearMeasured, nearLimit, 0.05 * nearLimit) << "near limit of the depth of field (mm)";
  EXPECT_NEAR(farMeasured, farLimit, 0.05 * farLimit) << "far limit of the depth of field (mm)";
}

}  // namespace
}  // namespace lensrt
