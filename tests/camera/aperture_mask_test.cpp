// Aperture masks: the lookup over the stop, and the bokeh of a point far
// behind the focus plane through the full lens: the mask's shape at the
// frame's centre, cut into a cat's eye near the corner by the lens's other
// apertures (a thin lens keeps its blur disk everywhere).
#include "camera/aperture_mask.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "camera/lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "optics/lens_readers.h"

namespace lensrt {
namespace {

// Texel centres of an n x n mask over [-1, 1]^2 (+y up), 1 inside `inside`.
template <class Inside>
ApertureMask maskOf(int n, Inside inside, const std::string& name) {
  std::vector<float> v(std::size_t(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const double x = (c + 0.5) * 2.0 / n - 1.0, y = 1.0 - (r + 0.5) * 2.0 / n;
      v[std::size_t(r) * n + c] = inside(x, y) ? 1.0f : 0.0f;
    }
  return ApertureMask(n, n, std::move(v), name);
}

// The equilateral triangle inscribed in the unit circle, apex up (+y).
bool inTriangle(double x, double y) {
  return y >= -0.5 && std::sqrt(3.0) * x <= 1.0 - y && -std::sqrt(3.0) * x <= 1.0 - y;
}
const double kTriangleOverDisk = 3.0 * std::sqrt(3.0) / 4.0 / kPi;  // 0.4135

TEST(ApertureMask, LooksUpTexelsUprightAcrossTheStop) {
  // Top row: white, black; bottom row: black, 50% grey.
  const ApertureMask m(2, 2, {1.0f, 0.0f, 0.0f, 0.5f}, "m.png");
  const double r = 4.0;
  EXPECT_EQ(m.transmittance({-2.0, 2.0}, r), 1.0);  // camera -X, +Y: top left
  EXPECT_EQ(m.transmittance({2.0, 2.0}, r), 0.0);
  EXPECT_EQ(m.transmittance({-2.0, -2.0}, r), 0.0);
  EXPECT_EQ(m.transmittance({2.0, -2.0}, r), 0.5);
  EXPECT_EQ(m.transmittance({-4.1, 2.0}, r), 0.0);  // beyond the image
  // A wide image: its width spans the diameter, its height less.
  const ApertureMask wide(4, 2, {1, 1, 1, 1, 1, 1, 1, 1}, "wide.png");
  EXPECT_EQ(wide.transmittance({3.9, 1.9}, r), 1.0);
  EXPECT_EQ(wide.transmittance({0.0, 2.1}, r), 0.0);
}

TEST(ApertureMask, MeanOverTheStopIsTheShapesAreaFraction) {
  EXPECT_EQ(maskOf(
                64, [](double, double) { return true; }, "white")
                .meanOverDisk(),
            1.0);
  EXPECT_NEAR(maskOf(512, inTriangle, "tri").meanOverDisk(), kTriangleOverDisk, 0.005);
}

TEST(ApertureMask, RefusesMasksItCannotUse) {
  EXPECT_THROW(ApertureMask(2, 2, {1, 1, 1}, "short"), std::invalid_argument);
  EXPECT_THROW(ApertureMask(0, 0, {}, "empty"), std::invalid_argument);
  EXPECT_THROW(ApertureMask(1, 1, {1.5f}, "bright"), std::invalid_argument);
  EXPECT_THROW(ApertureMask(1, 1, {std::numeric_limits<float>::quiet_NaN()}, "nan"), std::invalid_argument);
  EXPECT_THROW(ApertureMask(2, 2, {0, 0, 0, 0}, "black"), std::invalid_argument);
  // White only in a corner outside the stop's disk: black over the stop.
  EXPECT_THROW(maskOf(
                   16, [](double x, double y) { return x > 0.9 && y > 0.9; }, "corner"),
               std::invalid_argument);
  // Same name, other values: the description (the render's identity) differs.
  EXPECT_NE(ApertureMask(1, 1, {1.0f}, "a.png").describe(), ApertureMask(1, 1, {0.5f}, "a.png").describe());
}

double cross(const Vec2d& o, const Vec2d& a, const Vec2d& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Area of the convex hull (Andrew's monotone chain).
double hullArea(std::vector<Vec2d> p) {
  if (p.size() < 3) return 0.0;
  std::sort(p.begin(), p.end(),
            [](const Vec2d& a, const Vec2d& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2d> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  double area = 0.0;
  for (std::size_t i = 0; i + 1 < k; ++i) area += h[i].x * h[i + 1].y - h[i + 1].x * h[i].y;
  return 0.5 * std::abs(area);
}

struct Bokeh {
  std::vector<Vec2d> points;  // raster positions
  double area = 0.0;          // of their convex hull, px^2
};

Bokeh withHull(Bokeh b) {
  b.area = hullArea(b.points);
  return b;
}

// The exact bokeh of a point through the full lens: for each point of a
// grid over the rear-vertex plane, the raster position whose ray through it
// passes the point (Newton, test::imageOf); points the lens or the mask
// blocks give none.
Bokeh bokehOf(const LensCamera& camera, const Vec3d& point, Vec2d guess) {
  Bokeh b;
  constexpr int n = 40;
  const double r = camera.lens().rearApertureRadius();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec2d pupil{r * (2.0 * (i + 0.5) / n - 1.0), r * (2.0 * (j + 0.5) / n - 1.0)};
      const test::RaySource rays = [&](Vec2d raster) {
        return camera.traceThrough({float(raster.x), float(raster.y)}, pupil);
      };
      if (const auto x = test::imageOf(rays, point, guess)) b.points.push_back(*x);
    }
  return withHull(std::move(b));
}

// The same for the thin lens, by lens sample (its aperture sample does not
// depend on the film point).
Bokeh bokehOf(const ThinLensCamera& camera, const Vec3d& point, Vec2d guess) {
  Bokeh b;
  constexpr int n = 40;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (const auto x = test::imageOf(camera, point, {(i + 0.5) / n, (j + 0.5) / n}, guess))
        b.points.push_back(*x);
  return withHull(std::move(b));
}

TEST(ApertureMask, BokehTakesTheMasksShapeAtTheCentreAndACatsEyeInTheCorner) {
  // 100 um pixels on a full-frame sensor; dgauss-100mm wide open (f/2)
  // focused at 2 m; the point 50 m away, where its blur disk is about
  // f^2 / (N (s - f)) = 2.6 mm = 26 px across.
  const FilmGeometry film{360, 240, 36.0, 24.0};
  const LensPrescription rx = loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-100mm.lens");
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = 2.0;
  p.focusMetres = 2.0;
  const LensCamera open(Transform(), film, rx, p, Exposure{}, warnings);
  p.mask = std::make_shared<const ApertureMask>(maskOf(256, inTriangle, "triangle"));
  const LensCamera masked(Transform(), film, rx, p, Exposure{}, warnings);
  EXPECT_NE(masked.describe().find("mask=triangle 256x256 #"), std::string::npos) << masked.describe();

  const double z = -50.0;
  const Vec3d centre{0.0, 0.0, z};
  // Toward the top-right corner, 85% of the way (the image is inverted on
  // the film and upright in the picture: raster near (333, 20)).
  const Vec3d corner{0.85 * 18.0 / 100.0 * -z, 0.85 * 12.0 / 100.0 * -z, z};
  const Vec2d centreGuess{180.0, 120.0}, cornerGuess{180.0 + 0.85 * 180.0, 120.0 - 0.85 * 120.0};

  const Bokeh openCentre = bokehOf(open, centre, centreGuess),
              openCorner = bokehOf(open, corner, cornerGuess);
  const Bokeh maskCentre = bokehOf(masked, centre, centreGuess),
              maskCorner = bokehOf(masked, corner, cornerGuess);
  std::printf("bokeh areas (px^2): open centre %.1f corner %.1f; triangle centre %.1f corner %.1f\n",
              openCentre.area, openCorner.area, maskCentre.area, maskCorner.area);
  // The open stop's bokeh is the blur disk of the paraxial lens, of
  // diameter (f / N) (v_focus - v_point) / v_point (the hull of the grid's
  // points falls a grid step short of the rim: within 15%).
  const double f = open.lens().paraxial().efl, vFocus = f * 2000.0 / (2000.0 - f),
               vPoint = f * 50000.0 / (50000.0 - f);
  const double blurPx = (f / 2.0) * (vFocus - vPoint) / vPoint / 0.1;
  EXPECT_NEAR(openCentre.area / (kPi / 4.0 * blurPx * blurPx), 1.0, 0.15) << blurPx;
  // At the centre the triangle: its share of the disk (within 15%: the
  // lens's pupil aberrations stretch its rim, where the corners sit)...
  EXPECT_NEAR(maskCentre.area / openCentre.area, kTriangleOverDisk, 0.15 * kTriangleOverDisk);
  // ...upright (apex up; raster y grows downward): the centroid lies about
  // two thirds of the way down from the apex, and the top 30% of the
  // height is narrow (a disk's would be 0.92 of its full width).
  double top = 1e30, bottom = -1e30, cx = 0.0, cy = 0.0;
  for (const Vec2d& q : maskCentre.points)
    top = std::min(top, q.y), bottom = std::max(bottom, q.y), cx += q.x, cy += q.y;
  cx /= double(maskCentre.points.size());
  cy /= double(maskCentre.points.size());
  EXPECT_NEAR((cy - top) / (bottom - top), 0.62, 0.06);
  double halfWidth = 0.0, topHalfWidth = 0.0;
  for (const Vec2d& q : maskCentre.points) {
    halfWidth = std::max(halfWidth, std::abs(q.x - cx));
    if (q.y < top + 0.3 * (bottom - top)) topHalfWidth = std::max(topHalfWidth, std::abs(q.x - cx));
  }
  EXPECT_LT(topHalfWidth, 0.4 * halfWidth);
  // Near the corner the lens's other apertures cut both (cat's eye).
  EXPECT_LT(openCorner.area, 0.85 * openCentre.area);
  EXPECT_LT(maskCorner.area, 0.9 * maskCentre.area);

  // A thin lens of the same focal length and f-number blurs the point into
  // the same disk anywhere on the film.
  ThinLensParams t;
  t.focalLengthMm = open.lens().paraxial().efl;
  t.fNumber = 2.0;
  t.focusMetres = 2.0;
  const ThinLensCamera thin(Transform(), film, t, Exposure{});
  const Bokeh thinCentre = bokehOf(thin, centre, centreGuess),
              thinCorner = bokehOf(thin, corner, cornerGuess);
  std::printf("thin lens: centre %.1f corner %.1f\n", thinCentre.area, thinCorner.area);
  EXPECT_NEAR(thinCorner.area / thinCentre.area, 1.0, 0.03);
}

}  // namespace
}  // namespace lensrt
