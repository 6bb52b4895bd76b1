// The camera flags: parsing, the sensor crop, and how the factory derives the
// simpler models from a lens (thin: EFL and its f-number; pinhole: the lens's
// field of view at that focus) and focuses automatically.
#include <gtest/gtest.h>

#include <cmath>

#include "api/camera_factory.h"
#include "api/option_parsers.h"
#include "camera/camera_test_util.h"
#include "camera/pinhole_camera.h"
#include "camera/spec_test_util.h"
#include "camera/thin_lens_camera.h"
#include "core/constants.h"
#include "core/error.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

test::Flags withLens(const std::string& model) {
  test::Flags o;
  o("--camera", std::string(model));
  o("--lens", "dgauss-50mm");
  return o;
}

TEST(CameraSpec, ParsesSensorsAndShutterTimes) {
  EXPECT_EQ(parseSensor("aps-c"), (Vec2d{23.6, 15.6}));
  EXPECT_EQ(parseSensor("36x24"), (Vec2d{36, 24}));
  EXPECT_THROW(parseSensor("36x"), UsageError);
  EXPECT_THROW(parseSensor("big"), UsageError);
  EXPECT_DOUBLE_EQ(test::seconds("1/250"), 0.004);
  EXPECT_DOUBLE_EQ(test::seconds("2"), 2.0);
  EXPECT_EQ(test::seconds("0"), 0.0);  // an instant (motion blur off)
  EXPECT_THROW(test::seconds("-1/100"), UsageError);
  try {
    test::seconds("soon");
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--shutter"), std::string::npos) << e.what();
  }
}

TEST(CameraSpec, CropsTheSensorToTheImageAspect) {
  test::Flags o;
  const FilmGeometry wide = cameraFilm(o.spec.camera.sensorMm, 640, 360);  // 16:9 on 3:2: full width
  EXPECT_DOUBLE_EQ(wide.sensorWidthMm, 36.0);
  EXPECT_DOUBLE_EQ(wide.sensorHeightMm, 20.25);
  const FilmGeometry square = cameraFilm(o.spec.camera.sensorMm, 512, 512);  // full height
  EXPECT_DOUBLE_EQ(square.sensorWidthMm, 24.0);
  EXPECT_DOUBLE_EQ(square.sensorHeightMm, 24.0);
}

TEST(CameraSpec, ThinLensTakesTheLensFocalLengthAndFNumber) {
  Warnings w;
  const auto cam = test::makeCamera(withLens("thin"), CameraDesc{}, test::rasterFilm(64, 36), {}, w);
  const ParaxialData p =
      computeParaxial(loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-50mm.dat"));
  const CameraInfo i = cam->info();
  EXPECT_EQ(i.model, "thin");
  EXPECT_NEAR(i.focalLengthMm, p.efl, 1e-9);
  EXPECT_NEAR(i.fNumber, p.fNumber, 1e-9);
  EXPECT_TRUE(std::isinf(i.focusMetres)) << "nothing to hit: --focus auto falls back to infinity";
  const ImageMetadata m = cameraMetadata(*cam, Exposure{});
  EXPECT_EQ(m.at("lensrt:camera_model"), "thin");
  EXPECT_EQ(m.at("lensrt:lens"), "dgauss-50mm");
  EXPECT_EQ(m.at("lensrt:focus_m"), "inf");
  EXPECT_EQ(m.at("lensrt:sensor_mm"), "36x20.25");
}

// Focus breathing: the pinhole derived from a lens focused at s shows the
// field the lens shows; at infinity that is 2 atan(h / 2 EFL).
TEST(CameraSpec, PinholeGetsTheLensFieldOfViewAtItsFocus) {
  Warnings w;
  test::Flags o = withLens("pinhole");
  o("--focus", "inf");
  const auto far = test::makeCamera(o, CameraDesc{}, test::rasterFilm(64, 36), {}, w);
  const double efl = far->info().focalLengthMm;
  const ParaxialData p =
      computeParaxial(loadLens(std::string(LENSRT_SOURCE_DIR) + "/lenses/dgauss-50mm.dat"));
  EXPECT_NEAR(efl, p.efl, 1e-6);
  o("--focus", "0.5");
  const auto near = test::makeCamera(o, CameraDesc{}, test::rasterFilm(64, 36), {}, w);
  const double yfovNear = dynamic_cast<const PinholeCamera&>(*near).yfov();
  const double yfovFar = dynamic_cast<const PinholeCamera&>(*far).yfov();
  EXPECT_LT(yfovNear, yfovFar) << "the field narrows as the lens focuses closer";
  // The in-focus plane's half height seen from the entrance pupil: h u / (v s).
  const double s = 500, u = s + p.frontPrincipalZ - p.entrancePupilZ, v = p.efl * u / (u - p.efl);
  EXPECT_NEAR(yfovNear, 2 * std::atan(20.25 / 2 * u / (v * s)), 1e-9);
}

// --focus auto: the hit distance along the focus pixel's ray, projected on the axis.
TEST(CameraSpec, AutoFocusUsesTheAxialDistanceOfWhatThePixelSees) {
  Warnings w;
  test::Flags o;
  o("--camera", "thin");
  o("--focal-length", "50");
  o("--fstop", "4");
  o("--focus-pixel", "0,0");  // the top-left pixel: its ray is oblique
  Ray seen;
  const HitDistance hit = [&](const Ray& r) -> std::optional<double> {
    seen = r;
    return 3.0 / -r.direction.z;  // a wall 3 m in front, perpendicular to the axis
  };
  const auto cam = test::makeCamera(o, CameraDesc{}, test::rasterFilm(64, 36), hit, w);
  EXPECT_NEAR(cam->info().focusMetres, 3.0, 1e-4);
  EXPECT_LT(seen.direction.x, 0.0f);
  EXPECT_GT(seen.direction.y, 0.0f);
}

TEST(CameraSpec, UsageErrorsNameTheFlag) {
  Warnings w;
  const auto expectFlag = [&](test::Flags o, const std::string& flag) {
    try {
      test::makeCamera(o, CameraDesc{}, test::rasterFilm(64, 36), {}, w);
      ADD_FAILURE() << "no error for " << flag;
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find(flag), std::string::npos) << e.what();
    }
  };
  test::Flags thick;
  thick("--camera", "thick");
  expectFlag(thick, "--lens");
  test::Flags close = withLens("lens");
  close("--focus", "0.01");
  expectFlag(close, "--focus");
  test::Flags pixel;
  pixel("--camera", "thin");
  pixel("--focus-pixel", "500,2");
  expectFlag(pixel, "--focus-pixel");
}

// --film: the pinhole records radiance by default (weight 1 at every pixel:
// no cos^4), irradiance on request (cos^4 of the field angle, normalized
// exposure); the lens models refuse radiance.
TEST(CameraSpec, FilmIsRadianceForThePinholeAndIrradianceOnRequest) {
  Warnings w;
  CameraDesc gltf;
  gltf.yfov = float(60 * kPi / 180);
  CameraSample corner;
  corner.film = {0.0f, 0.0f};  // the top-left corner of a square image
  const double tanHalf = std::tan(30 * kPi / 180);
  const double cos2 = 1.0 / (1.0 + 2 * tanHalf * tanHalf);

  const auto radiance = test::makeCamera(test::Flags{}, gltf, test::rasterFilm(32, 32), {}, w);
  EXPECT_EQ(radiance->info().film, "radiance");
  EXPECT_EQ(cameraMetadata(*radiance, Exposure{}).at("lensrt:film"), "radiance");
  EXPECT_EQ(radiance->generateRay(corner)->weight, 1.0f);

  test::Flags irr;
  irr("--film", "irradiance");
  const auto irradiance = test::makeCamera(irr, gltf, test::rasterFilm(32, 32), {}, w);
  EXPECT_EQ(cameraMetadata(*irradiance, Exposure{}).at("lensrt:film"), "irradiance");
  EXPECT_NEAR(irradiance->generateRay(corner)->weight, cos2 * cos2, 1e-6);

  // Thin, thick and lens record irradiance, and say so.
  for (const char* model : {"thin", "thick", "lens"}) {
    EXPECT_EQ(test::makeCamera(withLens(model), gltf, test::rasterFilm(32, 32), {}, w)->info().film,
              "irradiance")
        << model;
    test::Flags o = withLens(model);
    o("--film", "radiance");
    try {
      test::makeCamera(o, gltf, test::rasterFilm(32, 32), {}, w);
      ADD_FAILURE() << model << " accepted --film radiance";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("--film"), std::string::npos) << e.what();
    }
  }
  // Physical exposure is a film irradiance: with the radiance film it is refused.
  test::Flags physical;
  physical("--exposure", "physical");
  EXPECT_THROW(test::makeCamera(physical, gltf, test::rasterFilm(32, 32), {}, w), UsageError);
  physical("--film", "irradiance");
  EXPECT_NO_THROW(test::makeCamera(physical, gltf, test::rasterFilm(32, 32), {}, w));
}

}  // namespace
}  // namespace lensrt
