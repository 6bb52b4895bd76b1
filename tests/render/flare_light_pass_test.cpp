// render/flare_light_pass: punctual lights through the full lens onto the
// film, against closed forms and the lens's own data:
// - the direct image of a distant point light (no reflections) carries the
//   irradiance at the lens times the entrance pupil's area (paraxial: EFL
//   over twice the f-number) times every surface's Fresnel transmittance at
//   normal incidence (from the indices), in film units of the camera's
//   exposure scale: within 3% (dgauss-50mm f/4 uncoated, 20 m: measured
//   0.18482 for 0.18361, 1.0066; taking the disc's area without its 20%
//   margin gives 0.699);
// - under spectral transport (the CIE observer) white light gives the same in
//   every channel;
// - on axis it is centred within 0.5 px, and ghosts only add;
// - the same bits on 1 and 2 threads;
// - the variance it reports is its noise: two seeds' images differ by it
//   (the mean square of (a - b) / sqrt(var a + var b) is 1 within 15% over
//   a defocused lamp's pixels).
#include "render/flare_light_pass.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/warnings.h"
#include "optics/lens_readers.h"
#include "render/film_response.h"

namespace lensrt {
namespace {

LensCamera flareCamera(int reflections) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = 4.0;
  p.focusMetres = kInfinity;
  p.coatings = Coating::None;
  p.flareReflections = reflections;
  const LensPrescription lens =
      loadLens(findLens("dgauss-50mm", std::filesystem::path(LENSRT_SOURCE_DIR) / "lenses"));
  return LensCamera(Transform(), FilmGeometry{320, 240, 36.0, 27.0}, lens, p, Exposure{}, warnings);
}

PunctualLight pointLight(const Vec3f& position) {
  PunctualLight l;
  l.type = PunctualLight::Type::Point;
  l.position = position;
  l.intensity = {1, 1, 1};
  return l;
}

struct Totals {
  double flux = 0, cx = 0, cy = 0;  // sum of red x pixel area / scale; its centroid (pixels)
};
Totals totals(const LensCamera& camera, const FlareImage& image, int channel = 0) {
  const FilmGeometry& f = camera.film();
  const double area = (f.sensorWidthMm / f.width) * (f.sensorHeightMm / f.height);
  Totals t;
  double w = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double v = image.at(x, y)[std::size_t(channel)];
      w += v, t.cx += v * (x + 0.5), t.cy += v * (y + 0.5);
    }
  t.flux = w * area / camera.exposureScale();
  t.cx /= w, t.cy /= w;
  return t;
}

TEST(FlareLightPass, TheDirectImageCarriesTheFluxThroughTheEntrancePupil) {
  const LensCamera camera = flareCamera(0);
  const double distance = 20.0;  // metres, down the axis (camera space looks down -z)
  const PunctualLight light = pointLight({0, 0, float(-distance)});
  const FlareImage image = flareLightPass(camera, std::span(&light, 1), 400000, 7);
  const Totals t = totals(camera, image);
  // Irradiance at the lens (1 W/sr at 20 m), the entrance pupil's area in mm^2.
  const ParaxialData& p = camera.lens().paraxial();
  const double pupilRadius = p.efl / (2 * p.fNumber);
  double transmittance = 1, before = 1;
  for (const Surface& s : camera.lens().prescription().surfaces) {
    const double n = s.medium.nd;
    transmittance *= 1 - std::pow((n - before) / (n + before), 2);
    before = n;
  }
  const double expected = 1.0 / (distance * distance) * kPi * pupilRadius * pupilRadius * transmittance;
  std::printf("direct image: %.5g for %.5g (T %.4f), centroid (%.3f, %.3f)\n", t.flux, expected,
              transmittance, t.cx, t.cy);
  EXPECT_NEAR(t.flux / expected, 1.0, 0.03);
  EXPECT_NEAR(t.cx, 160.0, 0.5);
  EXPECT_NEAR(t.cy, 120.0, 0.5);
  // Spectral transport: RGB (1, 1, 1) light is D65, which the CIE observer
  // records as (1, 1, 1): the same flux in every channel, within the noise
  // of the paths' wavelengths.
  const FlareImage spectral =
      flareLightPass(camera, std::span(&light, 1), 400000, 7, &FilmResponse::cie1931Srgb());
  for (int c = 0; c < 3; ++c) {
    const double f = totals(camera, spectral, c).flux;
    std::printf("spectral, channel %d: %.5g\n", c, f);
    EXPECT_NEAR(f / expected, 1.0, 0.03) << "channel " << c;
  }
}

// A directional light (a sun) straight down the axis: its irradiance times
// the same pupil and transmittance, centred.
TEST(FlareLightPass, TheSunsImageCarriesItsIrradianceThroughTheEntrancePupil) {
  const LensCamera camera = flareCamera(0);
  PunctualLight sun;
  sun.type = PunctualLight::Type::Directional;
  sun.direction = {0, 0, 1};  // travelling toward the camera, which looks down -z
  sun.intensity = {2, 2, 2};
  const FlareImage image = flareLightPass(camera, std::span(&sun, 1), 400000, 9);
  const Totals t = totals(camera, image);
  const ParaxialData& p = camera.lens().paraxial();
  double transmittance = 1, before = 1;
  for (const Surface& s : camera.lens().prescription().surfaces) {
    transmittance *= 1 - std::pow((s.medium.nd - before) / (s.medium.nd + before), 2);
    before = s.medium.nd;
  }
  const double expected = 2.0 * kPi * std::pow(p.efl / (2 * p.fNumber), 2) * transmittance;
  std::printf("sun: %.5g for %.5g, centroid (%.3f, %.3f)\n", t.flux, expected, t.cx, t.cy);
  EXPECT_NEAR(t.flux / expected, 1.0, 0.03);
  EXPECT_NEAR(t.cx, 160.0, 0.5);
  EXPECT_NEAR(t.cy, 120.0, 0.5);
}

TEST(FlareLightPass, GhostsAddLightAndTheBitsDoNotDependOnThreads) {
  const LensCamera direct = flareCamera(0), ghosts = flareCamera(2);
  const PunctualLight light = pointLight({1.0f, 0.5f, -20.0f});
  const FlareImage one = flareLightPass(ghosts, std::span(&light, 1), 300000, 3, nullptr, 1);
  const FlareImage two = flareLightPass(ghosts, std::span(&light, 1), 300000, 3, nullptr, 2);
  ASSERT_EQ(one.pixels.size(), two.pixels.size());
  EXPECT_EQ(0, std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(Rgb)));
  const double withGhosts = totals(ghosts, one).flux;
  const double without =
      totals(direct, flareLightPass(direct, std::span(&light, 1), 300000, 3, nullptr, 1)).flux;
  std::printf("with ghosts %.5g, direct alone %.5g\n", withGhosts, without);
  EXPECT_GT(withGhosts, without);
}

// Two independent passes of a lamp 0.3 m away, out of focus (the lens at
// infinity): a disc of about 20 pixels across, each taking many paths, where
// z = (a - b) / sqrt(var a + var b) has a mean square of 1 if the variances
// are right (over the pixels that took 20 paths or more: value^2 over
// variance, the deposits being alike). Any pixel reached reports a variance.
TEST(FlareLightPass, ItsVarianceIsItsNoise) {
  const LensCamera camera = flareCamera(0);
  const PunctualLight light = pointLight({0.01f, 0.0f, -0.3f});
  const FlareImage a = flareLightPass(camera, std::span(&light, 1), 1000000, 11, nullptr, 0, true);
  const FlareImage b = flareLightPass(camera, std::span(&light, 1), 1000000, 12, nullptr, 0, true);
  EXPECT_TRUE(flareLightPass(camera, std::span(&light, 1), 1000, 11).variance.empty()) << "only when asked";
  ASSERT_EQ(a.variance.size(), a.pixels.size());
  double sum = 0;
  int count = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double va = a.variance[i][c], vb = b.variance[i][c];
      const double pa = a.pixels[i][c], pb = b.pixels[i][c];
      if (pa != 0) {
        ASSERT_GT(va, 0) << "a pixel with deposits reports no variance";
      }
      if (!(pa != 0 && pb != 0 && pa * pa >= 20 * va && pb * pb >= 20 * vb)) continue;
      sum += (pa - pb) * (pa - pb) / (va + vb);
      ++count;
    }
  std::printf("mean z^2 over %d pixel channels that took 20 paths or more: %.4f\n", count, sum / count);
  ASSERT_GT(count, 300);
  EXPECT_NEAR(sum / count, 1.0, 0.15);
}

}  // namespace
}  // namespace lensrt
