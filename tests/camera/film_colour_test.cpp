// api/film_colour: the camera-to-XYZ fit over the ColorChecker and the film
// a camera response makes. A "camera" whose curves are the CIE observer's
// fits the identity exactly; real cameras reproduce the chart's colours
// close to the CIE observer's, its grey scale most closely.
#include "api/film_colour.h"

#include <gtest/gtest.h>

#include <cmath>

#include "camera/spec_test_util.h"
#include "color/cie.h"
#include "color/color_space.h"
#include "color/illuminant.h"
#include "sensor/color_checker.h"

namespace lensrt {
namespace {

double d65AtUnitY(double nm) {
  static const double y = spectrumToXyz([](double l) { return d65(l); }).y;
  return d65(nm) / y;
}

TEST(FilmColour, AnObserverAsACameraFitsTheIdentity) {
  SensorResponse cie;
  cie.name = "cie-as-camera";
  for (double nm = 360; nm <= 830; nm += 1) {
    cie.wavelengthsNm.push_back(nm);
    cie.rgb.push_back(cieXyzMatching(nm) / kCieYIntegral);
  }
  const Mat3d m = fitCameraToXyz(cie, d65AtUnitY);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(m(i, j), i == j ? 1.0 : 0.0, 1e-9) << i << "," << j;
}

// The film's record of a reflectance under D65 (at Y = 1): what a render of
// that card under RGB (1, 1, 1) light converges to.
Vec3d recorded(const FilmResponse& film, const ColorCheckerPatch& patch) {
  Vec3d sum{0, 0, 0};
  for (double nm = 360; nm <= 830; nm += 1)
    sum += Vec3d(film.curve(float(nm))) * (patch.at(nm) * d65AtUnitY(nm));
  return sum;
}

TEST(FilmColour, CamerasReproduceTheChartCloseToTheObserver) {
  Warnings warnings;
  for (const std::string camera :
       {"nikon-d850", "canon-eos-5d-mark-iv", "sony-ilce-7m3", "hasselblad-l1d-20c"}) {
    test::Flags options;
    options("--spectral", "on");  // what auto resolves to with a camera response (the plan's choice)
    options("--sensor-response", std::string(camera));
    options("--white-balance", "none");  // D65 is white: the chart as the observer sees it under D65
    const std::shared_ptr<const FilmResponse> film =
        filmColour(options.spec.colour, std::nullopt, warnings).response;
    ASSERT_TRUE(film);
    const Mat3d toSrgb = colorSpace(ColorSpaceId::Srgb).xyzToRgb;
    double sumError = 0, worstGrey = 0;
    int n = 0;
    for (std::size_t p = 0; p < colorCheckerPatches().size(); ++p) {
      const ColorCheckerPatch& patch = colorCheckerPatches()[p];
      const Vec3d got = recorded(*film, patch);
      const Vec3d want = toSrgb * spectrumToXyz([&](double nm) { return patch.at(nm) * d65AtUnitY(nm); });
      for (int c = 0; c < 3; ++c) sumError += std::abs(got[c] - want[c]), ++n;
      if (p >= 18)  // the grey scale: the observer's colour (the chart's greys are not quite neutral)
        for (int c = 0; c < 3; ++c)
          worstGrey = std::max(worstGrey, std::abs(got[c] / got.y - want[c] / want.y));
    }
    // A 3x3 cannot match an observer exactly (no camera meets the Luther
    // condition): about 0.01 of a reflectance on average.
    EXPECT_LT(sumError / n, 0.02) << camera;
    EXPECT_LT(worstGrey, 0.02) << camera;
  }
}

// A camera's own RGB (FilmColour::camera), checked against the curves
// themselves: the image of any card, taken back to camera RGB, is what the
// curves record of it (in units of D65's green); the output space "camera"
// is camera RGB itself; the white balance's light is the neutral.
TEST(FilmColour, CameraRgbIsWhatTheCurvesRecord) {
  Warnings warnings;
  const SensorResponse sensor = loadSensorResponse("sony-ilce-7m3");
  Vec3d green{0, 0, 0}, tungsten{0, 0, 0};
  for (double nm = 360; nm <= 830; nm += 1) {
    green += sensor.at(nm) * d65AtUnitY(nm);
    tungsten += sensor.at(nm) * blackbodySpectrum(3000, nm);
  }
  for (const char* space : {"srgb", "acescg", "camera"}) {
    test::Flags options;
    options("--spectral", "on");  // what auto resolves to with a camera response (the plan's choice)
    options("--sensor-response", "sony-ilce-7m3");
    options("--output-space", std::string(space));
    options("--white-balance", "3000");
    const FilmColour colour = filmColour(options.spec.colour, std::nullopt, warnings);
    ASSERT_TRUE(colour.camera) << space;
    for (std::size_t p : {0u, 5u, 14u, 19u}) {
      const ColorCheckerPatch& patch = colorCheckerPatches()[p];
      Vec3d curves{0, 0, 0};
      for (double nm = 360; nm <= 830; nm += 1) curves += sensor.at(nm) * (patch.at(nm) * d65AtUnitY(nm));
      const Vec3d camera = colour.camera->fromImage * recorded(*colour.response, patch);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(camera[c], curves[c] / green.y, 2e-3 * std::abs(curves.y / green.y))
            << space << " patch " << p << " channel " << c;
      if (std::string(space) == "camera") {
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j)
            EXPECT_NEAR(colour.camera->toImage(i, j), i == j ? 1.0 : 0.0, 1e-3) << i << "," << j;
      }
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(colour.camera->asShotNeutral[c], tungsten[c] / tungsten.y, 1e-3);
  }
  // The CIE observer has no camera RGB: the image's is the sensor's.
  EXPECT_FALSE(filmColour(ColourSpec{}, std::nullopt, warnings).camera);
}

}  // namespace
}  // namespace lensrt
