// Dispersion in renders through the seed's double Gauss (dgauss-100mm, with
// its glasses' Abbe numbers): a grey sky keeps its colour, and a small white
// emitter near the frame edge splits into R and B images as far apart as the
// tracer's lateral colour predicts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <tuple>

#include "camera/film_mapping.h"
#include "camera/lens_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "optics/distortion.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"
#include "render/environment.h"
#include "render/integrator.h"
#include "render/lights.h"
#include "render/material_eval.h"
#include "render/renderer.h"
#include "render/spectral_response.h"
#include "render_test_util.h"
#include "scene/render_scene.h"

namespace lensrt {
namespace {

LensPrescription dgauss100Prescription() {
  return loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-100mm.lens");
}

LensCamera dgauss100(const FilmGeometry& film, double fNumber, double focusM, bool dispersion) {
  Warnings warnings;
  LensCameraParams p;
  p.fNumber = fNumber;
  p.focusMetres = focusM;
  p.dispersion = dispersion;
  return LensCamera(Transform(), film, dgauss100Prescription(), p, Exposure{}, warnings);
}

Image render(SceneDesc desc, const Camera& camera, const Environment& env, RenderSettings rs) {
  const RenderScene scene(std::move(desc));
  const MaterialTable materials(scene.desc());
  const LightSet lights(materials, env, scene.bounds());
  IntegratorSettings is;
  is.maxDepth = 1;
  const Integrator integrator(scene, materials, lights, env, is);
  return renderImage(camera, integrator, rs).image;
}

double channelMean(const Image& img, const char* name) {
  const int c = img.channelIndex(name);
  double sum = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += img.at(x, y, c);
  return sum / (double(img.width) * img.height);
}

TEST(DispersionRender, GreySkyKeepsItsColourAndMean) {
  const FilmGeometry film{36, 24, 36.0, 24.0};
  const LensCamera on = dgauss100(film, 2.0, 10.0, true), off = dgauss100(film, 2.0, 10.0, false);
  ASSERT_TRUE(on.tracesWavelengths());
  ASSERT_FALSE(off.tracesWavelengths());
  RenderSettings rs;
  rs.samplesPerPixel = 64;
  rs.seed = 5;
  rs.aovs.variance = true;
  // Nothing to see but the grey sky: the square sits behind the camera.
  const Environment sky = Environment::constant({0.5f, 0.5f, 0.5f});
  const Image a = render(test::squareScene(-5.0f, 0.1f, 0.0f), on, sky, rs);
  const Image b = render(test::squareScene(-5.0f, 0.1f, 0.0f), off, sky, rs);
  const double r = channelMean(a, "R"), g = channelMean(a, "G"), bl = channelMean(a, "B");
  std::printf("dispersion on: mean R %.5f G %.5f B %.5f; off: G %.5f\n", r, g, bl, channelMean(b, "G"));
  EXPECT_NEAR(r / g, 1.0, 0.01);
  EXPECT_NEAR(bl / g, 1.0, 0.01);
  // Only the geometry varies with wavelength: the exposure is the d line's.
  EXPECT_NEAR(g / channelMean(b, "G"), 1.0, 0.01);
}

// The extra noise of the wavelengths: the variance of each pixel's value
// over renders with different seeds, dispersion on against off. Each pixel's
// wavelengths are stratified, so the per-sample weights (0 to 3) average out.
TEST(DispersionRender, GreySkyNoiseRatio) {
  const FilmGeometry film{36, 24, 36.0, 24.0};
  const LensCamera on = dgauss100(film, 2.0, 10.0, true), off = dgauss100(film, 2.0, 10.0, false);
  const Environment sky = Environment::constant({0.5f, 0.5f, 0.5f});
  const int seeds = 8;
  const auto variance = [&](const Camera& cam, const char* channel) {
    std::vector<double> sum(film.width * film.height), sum2(sum.size());
    for (int seed = 0; seed < seeds; ++seed) {
      RenderSettings rs;
      rs.samplesPerPixel = 16;
      rs.seed = std::uint64_t(seed);
      const Image img = render(test::squareScene(-5.0f, 0.1f, 0.0f), cam, sky, rs);
      const int c = img.channelIndex(channel);
      for (int y = 0; y < film.height; ++y)
        for (int x = 0; x < film.width; ++x) {
          const double v = img.at(x, y, c);
          sum[y * film.width + x] += v;
          sum2[y * film.width + x] += v * v;
        }
    }
    double total = 0;
    for (std::size_t i = 0; i < sum.size(); ++i) total += (sum2[i] - sum[i] * sum[i] / seeds) / (seeds - 1);
    return total / double(sum.size());
  };
  for (const char* c : {"R", "G", "B"}) {
    const double vOn = variance(on, c), vOff = variance(off, c);
    std::printf("per-pixel variance of %s at 16 spp: on %.3g, off %.3g, ratio %.2f\n", c, vOn, vOff,
                vOn / vOff);
    // Measured about 3 (the weights' spread times the vignetting's 0/1
    // noise); unstratified wavelengths would multiply it by ~10.
    EXPECT_LT(vOn / vOff, 5.0) << c;
  }
}

// Without dispersion data the camera does not trace wavelengths.
TEST(DispersionRender, LensWithoutAbbeNumbersStaysAtTheDLine) {
  Warnings warnings;
  LensCameraParams p;
  p.dispersion = true;
  LensPrescription rx = dgauss100Prescription();
  for (Surface& s : rx.surfaces) s.medium.vd = 0.0;
  const LensCamera cam(Transform(), FilmGeometry{16, 16, 36.0, 24.0}, rx, p, Exposure{}, warnings);
  EXPECT_FALSE(cam.tracesWavelengths());
  EXPECT_FALSE(cam.info().dispersion);
}

// Same seed, same bits: one thread or two, any tile size, one pass or many.
TEST(DispersionRender, DeterministicAcrossThreadsTilesAndPasses) {
  const FilmGeometry film{24, 16, 36.0, 24.0};
  const LensCamera cam = dgauss100(film, 2.0, 3.0, true);
  const SceneDesc scene = test::rectangleScene(-0.2f, 0.6f, -0.3f, 0.4f, 3.0f, 1.0f);
  const Environment sky = Environment::constant({0.2f, 0.3f, 0.4f});
  RenderSettings rs;
  rs.samplesPerPixel = 13;
  rs.seed = 9;
  rs.threads = 1;
  rs.tileSize = 16;
  const Image one = render(scene, cam, sky, rs);
  rs.threads = 2;
  rs.tileSize = 5;
  const Image two = render(scene, cam, sky, rs);
  ASSERT_EQ(one.pixels.size(), two.pixels.size());
  EXPECT_EQ(std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)), 0);

  // In passes of 1, 2, 4, ... samples (the scale-out loop).
  const RenderScene rscene{SceneDesc(scene)};
  const MaterialTable materials(rscene.desc());
  const LightSet lights(materials, sky, rscene.bounds());
  IntegratorSettings is;
  is.maxDepth = 1;
  const Integrator integrator(rscene, materials, lights, sky, is);
  FilmState state(PixelRegion::wholeFrame(film.width, film.height), rs.aovs);
  PassControl control;
  control.passSeconds = 1e9;  // every pass doubles
  int passes = 0;
  control.afterPass = [&](const FilmState&) { ++passes; };
  ASSERT_TRUE(renderPasses(cam, integrator, rs, state, &control));
  EXPECT_GE(passes, 2);
  const Image passed = renderOutput(cam, state).image;
  ASSERT_EQ(one.pixels.size(), passed.pixels.size());
  EXPECT_EQ(std::memcmp(one.pixels.data(), passed.pixels.data(), one.pixels.size() * sizeof(float)), 0);
}

// The emitter of the lateral-colour tests: a 10 cm white square 100 m away,
// 17 m right of the axis, seen at f/8 focused on it. Its image lies at about
// 0.95 of the half width of a 36x24 mm sensor of 5 um pixels; only a 48x48
// crop around it is rendered, at 256 spp.
constexpr double distanceM = 100.0, offsetM = 17.0, sizeM = 0.1, fNumber = 8.0;
const FilmGeometry kEdgeFilm{7200, 4800, 36.0, 24.0};

SceneDesc edgeEmitterScene() {
  const float h = float(sizeM / 2);
  return test::rectangleScene(float(offsetM) - h, float(offsetM) + h, -h, h, float(distanceM), 1.0f);
}

// Renders the crop centred on raster column cx, on the film's middle row.
Image renderEdgeEmitter(const Camera& camera, int cx) {
  RenderSettings rs;
  rs.samplesPerPixel = 256;
  rs.seed = 1;
  const int cy = kEdgeFilm.height / 2;
  rs.region = PixelRegion{cx - 24, cx + 24, cy - 24, cy + 24};
  return render(edgeEmitterScene(), camera, Environment(), rs);
}

// At f/8 the blur is small and symmetric, so each channel's centroid is the
// chief ray's image height averaged over that channel's spectral response:
// the prediction, from the tracer.
TEST(DispersionRender, EdgeEmitterSplitsByThePredictedLateralColour) {
  const FilmGeometry& film = kEdgeFilm;
  const LensCamera on = dgauss100(film, fNumber, distanceM, true);
  const LensCamera off = dgauss100(film, fNumber, distanceM, false);

  // The prediction: at each wavelength, the centroid on the film of the
  // rays from the emitter's centre that pass the lens (a uniform grid over
  // the aim plane: equal flux per ray for an object this far), weighted by
  // the R and B responses.
  const LensSystem& lens = on.lens();
  const FieldPoint field{std::atan(offsetM / distanceM) * 180.0 / M_PI, distanceM * 1000.0};
  const double filmZ = on.filmZ();
  const auto spotCentroidX = [&](double wl) {
    const std::optional<AimInterval> band = meridionalPassBand(lens, field, wl);
    EXPECT_TRUE(band) << wl;
    if (!band) return 0.0;
    const double mid = 0.5 * (band->lo + band->hi), half = 0.6 * (band->hi - band->lo);
    double sum = 0;
    int n = 0;
    for (int i = 0; i < 40; ++i)
      for (int j = 0; j < 40; ++j) {
        const Vec2d aim{mid + half * ((i + 0.5) / 20 - 1), half * ((j + 0.5) / 20 - 1)};
        const std::optional<LensRay> out = lens.traceFromScene(fieldRay(lens, field, aim), wl);
        if (!out) continue;
        sum += out->origin.x + out->direction.x * (filmZ - out->origin.z) / out->direction.z;
        ++n;
      }
    return sum / n;
  };
  double hR = 0, hB = 0, wR = 0, wB = 0;
  for (double wl = kWavelengthMinNm + 2.5; wl < kWavelengthMaxNm; wl += 5.0) {
    const Rgb r = spectralResponse(wl);
    if (r.x + r.z < 1e-6f) continue;
    const double x = spotCentroidX(wl);
    hR += r.x * x, wR += r.x;
    hB += r.z * x, wB += r.z;
  }
  // Film x is inverted (negative for this field); the picture is upright.
  const double xR = rasterOfUprightSensorPointMm(film, {-hR / wR, 0.0}).x;
  const double xB = rasterOfUprightSensorPointMm(film, {-hB / wB, 0.0}).x;
  const double predictedPx = xR - xB;
  const double xD = rasterOfUprightSensorPointMm(film, {-spotCentroidX(kWavelengthDNm), 0.0}).x;

  const int cx = int(std::lround(xD));
  const Image a = renderEdgeEmitter(on, cx);
  const Image b = renderEdgeEmitter(off, cx);
  const test::Centroid rOn = test::centroid(a, "R"), bOn = test::centroid(a, "B");
  const test::Centroid rOff = test::centroid(b, "R"), bOff = test::centroid(b, "B");
  std::printf(
      "d-line centroid at x = %.3f px; R centroid %.3f, B %.3f: R - B = %.3f px (%.3f um), "
      "predicted %.3f px\n",
      xD, rOn.x, bOn.x, rOn.x - bOn.x, (rOn.x - bOn.x) * 5.0, predictedPx);
  ASSERT_GT(std::abs(predictedPx), 0.3);  // well above the centroids' noise
  EXPECT_NEAR(rOn.x - bOn.x, predictedPx, 0.1 * std::abs(predictedPx));
  EXPECT_NEAR(rOn.y, bOn.y, 0.05);
  EXPECT_NEAR(rOff.x, bOff.x, 0.05);
  EXPECT_NEAR(rOff.y, bOff.y, 0.05);
}

// The same emitter through the thin and thick lens derived from the same
// double Gauss, dispersion on: each wavelength has its own focal length, so
// the blur differs per channel (axial colour). The thin lens's chief ray
// passes its centre undeviated: no lateral colour, the R and B centroids
// coincide. The thick lens keeps the lens's pupils and principal planes, so
// its chief ray (through the pupil centres) crosses H' off the axis, at
// a = -x (1 - s), s = (H' - film) / (XP - film), and is bent there by the
// power of its wavelength: the centroid of wavelength l lands at the upright
// film x = X / (D / v - (1 - s) (1 - D / u(l))) for an emitter X to the side
// and D in front of H, with 1/u(l) = 1/f(l) - 1/v. That small lateral colour
// of the model (opposite in sign to the real lens's here) is checked
// against this closed form, averaged over the R and B responses.
TEST(DispersionRender, EdgeEmitterThroughTheThinAndThickLens) {
  const FilmGeometry& film = kEdgeFilm;
  const LensPrescription rx = dgauss100Prescription();
  const ParaxialData paraxial = computeParaxial(rx);
  ThinLensParams thinParams;
  thinParams.focalLengthMm = paraxial.efl;
  thinParams.fNumber = fNumber;
  thinParams.focusMetres = distanceM;
  thinParams.dispersion.emplace(rx);
  ThickLensParams thickParams = thickLensFromParaxial(paraxial, fNumber, distanceM);
  thickParams.dispersion.emplace(rx);
  const ThinLensCamera thin(Transform(), film, thinParams);
  const ThickLensCamera thick(Transform(), film, thickParams);
  ASSERT_TRUE(thin.tracesWavelengths());
  ASSERT_TRUE(thick.tracesWavelengths());

  // The thick lens's closed form, per wavelength and weighted by R and B.
  const ThickLensParams& P = thick.params();
  const double v = thick.imageDistance(),
               sRatio = (P.rearPrincipalZ - thick.filmZ()) / (P.exitPupilZ - thick.filmZ());
  const double D = distanceM * 1000.0 + P.frontPrincipalZ - P.entrancePupilZ, X = offsetM * 1000.0;
  const auto thickX = [&](double wl) {
    const double invU = 1.0 / (P.focalLengthMm * P.dispersion->at(float(wl))) - 1.0 / v;
    return X / (D / v - (1.0 - sRatio) * (1.0 - D * invU));
  };
  double hR = 0, hB = 0, wR = 0, wB = 0;
  for (double wl = kWavelengthMinNm + 2.5; wl < kWavelengthMaxNm; wl += 5.0) {
    const Rgb r = spectralResponse(wl);
    hR += r.x * thickX(wl), wR += r.x;
    hB += r.z * thickX(wl), wB += r.z;
  }
  const double thickPredictedPx = rasterOfUprightSensorPointMm(film, {hR / wR, 0.0}).x -
                                  rasterOfUprightSensorPointMm(film, {hB / wB, 0.0}).x;

  for (const auto& [name, camera, imageDistanceMm, predictedPx] :
       {std::tuple<const char*, const Camera*, double, double>{"thin", &thin, thin.imageDistanceMm(), 0.0},
        std::tuple<const char*, const Camera*, double, double>{"thick", &thick, v, thickPredictedPx}}) {
    SCOPED_TRACE(name);
    // Around the image of the emitter's centre in the upright picture.
    const double uprightX = imageDistanceMm * offsetM / distanceM;
    const int cx = int(std::lround(rasterOfUprightSensorPointMm(film, {uprightX, 0.0}).x));
    const Image img = renderEdgeEmitter(*camera, cx);
    const test::Centroid r = test::centroid(img, "R"), b = test::centroid(img, "B");
    std::printf("%s lens: R centroid %.3f, B %.3f: R - B = %.3f px, predicted %.3f px\n", name, r.x, b.x,
                r.x - b.x, predictedPx);
    EXPECT_NEAR(r.x, cx, 2.0);  // the emitter is inside the rendered region
    EXPECT_NEAR(r.x - b.x, predictedPx, std::max(0.05, 0.1 * std::abs(predictedPx)));
    EXPECT_NEAR(r.y, b.y, 0.05);
  }
  ASSERT_GT(thickPredictedPx, 0.2);  // measurable, and of the other sign than the full lens's -0.57 px
}

}  // namespace
}  // namespace lensrt
