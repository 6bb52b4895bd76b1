// A receding ground plane through a wide-open thin lens: with the tilt the
// hinge rule gives, sharp from near to far; untilted, sharp only at the focus
// distance. Rendered through the whole renderer (render_test_util).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <utility>

#include "camera/thin_lens_camera.h"
#include "camera_test_util.h"
#include "core/constants.h"
#include "render_test_util.h"

namespace lensrt {
namespace {

// 288 x 192 pixels of 0.125 mm on 36 x 24 mm; a 50 mm f/0.8 lens 0.7 m
// above the ground, level (an ideal thin lens that fast: blur discs of
// about 3 pixels at the near and far ends when focused at 5 m).
constexpr double kF = 50.0, kHeightM = 0.7, kPixelMm = 0.125;
constexpr int kWidth = 288, kHeight = 192;

// Emissive bars across the ground plane Y = -height, each 2 pixels tall in
// the picture (their edges at image heights -k 0.25 mm, k = 4..48, from
// y = -h f / z), every other one lit: a square wave of period 4 pixels from
// 2.9 m to 35 m.
SceneDesc groundBars() {
  SceneDesc s;
  s.sourceFile = "tilt render test (in code)";
  Mesh m;
  m.name = "bars";
  const float y = float(-kHeightM), half = 40.0f;
  for (int k = 4; k < 48; k += 2) {
    const float zFar = float(-kHeightM * kF / (k * 2 * kPixelMm));
    const float zNear = float(-kHeightM * kF / ((k + 1) * 2 * kPixelMm));
    const auto first = std::uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(),
                       {{-half, y, zNear}, {half, y, zNear}, {half, y, zFar}, {-half, y, zFar}});
    m.indices.insert(m.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
  m.material = 0;
  s.meshes.push_back(std::move(m));
  Material mat;
  mat.baseColor = {0, 0, 0, 1};
  mat.metallic = 0;
  mat.emissive = {1, 1, 1};
  mat.doubleSided = true;
  s.materials.push_back(mat);
  s.instances.push_back({0, Transform()});
  return s;
}

// RMS contrast (standard deviation over mean) of the row profile (the mean
// over the middle half of the columns) in rows [y0, y1).
double contrast(const test::RenderedImage& img, int y0, int y1) {
  double sum = 0.0, sum2 = 0.0;
  for (int y = y0; y < y1; ++y) {
    double row = 0.0;
    for (int x = kWidth / 4; x < 3 * kWidth / 4; ++x) row += img.image.at(x, y, img.red);
    row /= kWidth / 2;
    sum += row;
    sum2 += row * row;
  }
  const double n = y1 - y0, mean = sum / n;
  return std::sqrt(std::max(0.0, sum2 / n - mean * mean)) / mean;
}

struct Contrasts {
  double nearEnd, focus, farEnd;
};
// Near: 3.0-3.4 m (the frame's bottom); around 5 m (4.5-5.6 m); far: 12-25 m.
Contrasts contrasts(const ThinLensParams& p) {
  FilmGeometry film;
  film.width = kWidth;
  film.height = kHeight;
  const ThinLensCamera cam(Transform(), film, p);
  const test::RenderedImage img = test::renderScene(groundBars(), cam, Environment(), 16);
  return {contrast(img, 178, 190), contrast(img, 146, 158), contrast(img, 107, 119)};
}

TEST(TiltRender, HingeRuleTiltKeepsARecedingGroundSharp) {
  // The plane of focus is the ground when the hinge line (J = f / sin t from
  // the lens, in the plane through it parallel to the film: J cos t below
  // the axis) lies on it and the Scheimpflug line too (focus at infinity,
  // v = f): tan t = f / h.
  const double tiltDegrees = std::atan(kF / (kHeightM * 1000.0)) * 180.0 / kPi;
  ThinLensParams p;
  p.focalLengthMm = kF;
  p.focusMetres = kInfinity;
  p.movements.tiltDegrees = tiltDegrees;
  p.fNumber = 64;  // the in-focus level: everything sharp
  const Contrasts sharp = contrasts(p);
  p.fNumber = 0.8;
  const Contrasts tilted = contrasts(p);
  std::printf("tilt %.3f deg, f/0.8: contrast near %.3f far %.3f (f/64: %.3f, %.3f)\n", tiltDegrees,
              tilted.nearEnd, tilted.farEnd, sharp.nearEnd, sharp.farEnd);
  EXPECT_GT(tilted.nearEnd, 0.9 * sharp.nearEnd);
  EXPECT_GT(tilted.farEnd, 0.9 * sharp.farEnd);
  EXPECT_GT(tilted.focus, 0.9 * sharp.focus);

  // Untilted and focused at 5 m: sharp there only (the ends keep under 60%).
  p.movements = {};
  p.focusMetres = 5.0;
  p.fNumber = 64;
  const Contrasts flatSharp = contrasts(p);
  p.fNumber = 0.8;
  const Contrasts flat = contrasts(p);
  std::printf("no tilt, focus 5 m, f/0.8: contrast near %.3f at 5 m %.3f far %.3f (f/64: %.3f, %.3f, %.3f)\n",
              flat.nearEnd, flat.focus, flat.farEnd, flatSharp.nearEnd, flatSharp.focus, flatSharp.farEnd);
  EXPECT_GT(flat.focus, 0.9 * flatSharp.focus);
  EXPECT_LT(flat.nearEnd, 0.6 * flatSharp.nearEnd);
  EXPECT_LT(flat.farEnd, 0.6 * flatSharp.farEnd);
}

}  // namespace
}  // namespace lensrt
