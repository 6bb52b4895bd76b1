// lensrt render writes OpenEXR's standard attributes with their types, so
// that other tools read the camera (aperture, focus, expTime, isoSpeed,
// worldToCamera, chromaticities, capDate, and OpenEXR 3.2's lens and sensor
// attributes), beside the lensrt:* strings.
#include <ImfChromaticitiesAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfInputFile.h>
#include <ImfMatrixAttribute.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::TempDir;

TEST(ExrStandardAttributes, DescribeTheCameraWithTheirTypes) {
  const TempDir dir;
  const std::string out = (dir / "a.exr").string();
  const cli::RunResult r = runLensrt({"render",     std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf",
                                      "--camera",   "thin",
                                      "--fstop",    "5.6",
                                      "--focus",    "2",
                                      "--exposure", "physical",
                                      "--shutter",  "1/250",
                                      "--iso",      "400",
                                      "--res",      "32x18",
                                      "--spp",      "1",
                                      "-q",         "-o",
                                      out});
  ASSERT_EQ(r.status, 0) << r.err;
  Imf::InputFile file(out.c_str());
  const Imf::Header& h = file.header();
  ASSERT_TRUE(Imf::hasAperture(h) && Imf::hasFocus(h) && Imf::hasExpTime(h) && Imf::hasIsoSpeed(h));
  EXPECT_FLOAT_EQ(Imf::aperture(h), 5.6f);
  EXPECT_FLOAT_EQ(Imf::focus(h), 2.0f);
  EXPECT_FLOAT_EQ(Imf::expTime(h), 0.004f);
  EXPECT_FLOAT_EQ(Imf::isoSpeed(h), 400.0f);
  ASSERT_TRUE(Imf::hasCapDate(h));
  ASSERT_TRUE(Imf::hasChromaticities(h));
  const Imf::Chromaticities c = Imf::chromaticities(h);  // Rec.709 / sRGB, D65
  EXPECT_FLOAT_EQ(c.red.x, 0.64f);
  EXPECT_FLOAT_EQ(c.white.y, 0.329f);
  // dof_row's camera stands at (0, 1.2, 0) looking down -Z (glTF): OpenEXR's
  // camera space looks down +Z, so a point 3 m in front lands at z = +3.
  ASSERT_TRUE(Imf::hasWorldToCamera(h));
  const Imath::M44f& m = Imf::worldToCamera(h);
  const Imath::V3f eye = Imath::V3f(0.0f, 1.2f, 0.0f) * m, ahead = Imath::V3f(0.0f, 1.2f, -3.0f) * m;
  EXPECT_NEAR(eye.length(), 0.0f, 1e-5f);
  EXPECT_NEAR(ahead.z, 3.0f, 1e-5f);
  EXPECT_NEAR(ahead.x, 0.0f, 1e-5f);
}

// OpenEXR 3.2's lens and sensor attributes, as numbers (Debian's OpenEXR 3.1
// has no accessors for them, so they are read by name and type): the lens's
// name, its focal length (the EXR's lensrt:focal_length_mm), the photosite
// pitch in microns (sensor width / pixels) and the sensor in mm.
TEST(ExrStandardAttributes, NameTheLensAndTheSensor) {
  const TempDir dir;
  const std::string out = (dir / "a.exr").string();
  const cli::RunResult r = runLensrt({"render", std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf",
                                      "--camera", "lens", "--lens", "dgauss-50mm", "--sensor", "aps-c",
                                      "--res", "40x24", "--spp", "1", "-q", "-o", out});
  ASSERT_EQ(r.status, 0) << r.err;
  Imf::InputFile file(out.c_str());
  const Imf::Header& h = file.header();
  const auto* lens = h.findTypedAttribute<Imf::StringAttribute>("lensModel");
  ASSERT_TRUE(lens);
  EXPECT_EQ(lens->value(), "dgauss-50mm");
  const auto* focal = h.findTypedAttribute<Imf::FloatAttribute>("effectiveFocalLength");
  const auto* nominal = h.findTypedAttribute<Imf::FloatAttribute>("nominalFocalLength");
  const auto* pitch = h.findTypedAttribute<Imf::FloatAttribute>("sensorPhotositePitch");
  const auto* sensor = h.findTypedAttribute<Imf::V2fAttribute>("sensorOverallDimensions");
  const auto* text = h.findTypedAttribute<Imf::StringAttribute>("lensrt:focal_length_mm");
  ASSERT_TRUE(focal && nominal && pitch && sensor && text);
  EXPECT_NEAR(focal->value(), std::stof(text->value()), 0.01f);
  EXPECT_NEAR(focal->value(), 50.0f, 2.0f);  // dgauss-50mm
  EXPECT_FLOAT_EQ(nominal->value(), std::round(focal->value()));
  // aps-c is 23.6 x 15.6 mm, cropped to the frame's 5:3: 23.6 x 14.16 mm.
  EXPECT_NEAR(sensor->value().x, 23.6f, 1e-4f);
  EXPECT_NEAR(sensor->value().y, 23.6f * 24 / 40, 1e-4f);
  EXPECT_NEAR(pitch->value(), 23.6f * 1000 / 40, 1e-3f);
}

// entrancePupilOffset (mm from the film to the entrance pupil) and worldToNDC
// against the closed form. Through the thin lens (f 50 mm focused at 2 m
// from it) the film stands v = f D / (D - f) = 51.282 mm behind the lens,
// the pupil; through the pinhole (35 mm) at 35 mm. A camera-space point
// (x, y, -z) then images at v x / z, v y / z on the 36 x 24 mm film, so
// its NDC is (0.5 + v x / (36 z), 0.5 - v y / (24 z)) (top left (0, 0)).
// dof_row's camera stands at (0, 1.2, 0) looking down -Z. A film shifted by
// (sx, sy) mm shows at its centre what the unshifted film showed at (sx, sy)
// (x right, y up): its NDC is (0.5 + (v x / z - sx) / 36, 0.5 - (v y / z - sy)
// / 24). OpenImageIO's iinfo reads both as numbers.
TEST(ExrStandardAttributes, EntrancePupilOffsetAndWorldToNdcMatchTheClosedForm) {
  const TempDir dir;
  struct Case {
    std::vector<std::string> camera;
    double filmToPupilMm;
    double shiftX = 0, shiftY = 0;
  };
  const double f = 50, d = 2000;
  for (const Case& c :
       {Case{{"--camera", "pinhole", "--focal-length", "35"}, 35.0},
        Case{{"--camera", "thin", "--focal-length", "50", "--fstop", "8", "--focus", "2"}, f * d / (d - f)},
        Case{{"--camera", "thin", "--focal-length", "50", "--fstop", "8", "--focus", "2", "--shift", "3,-2"},
             f * d / (d - f),
             3,
             -2}}) {
    SCOPED_TRACE(c.camera[1] + (c.shiftX != 0 ? " shifted" : ""));
    const std::string out = (dir / "a.exr").string();
    std::vector<std::string> args = {"render",   std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf",
                                     "--sensor", "36x24",
                                     "--res",    "48x32",
                                     "--spp",    "1",
                                     "-q",       "-o",
                                     out};
    args.insert(args.end(), c.camera.begin(), c.camera.end());
    const cli::RunResult r = runLensrt(args);
    ASSERT_EQ(r.status, 0) << r.err;
    Imf::InputFile file(out.c_str());
    const Imf::Header& h = file.header();
    const auto* pupil = h.findTypedAttribute<Imf::FloatAttribute>("entrancePupilOffset");
    ASSERT_TRUE(pupil);
    EXPECT_NEAR(pupil->value(), c.filmToPupilMm, 1e-3);
    ASSERT_TRUE(Imf::hasWorldToNDC(h));
    const Imath::M44f& m = Imf::worldToNDC(h);
    const double v = c.filmToPupilMm;
    for (const Imath::V3f world : {Imath::V3f(0.1f, 1.25f, -2.0f), Imath::V3f(-0.7f, 0.4f, -5.0f)}) {
      const Imath::V3f ndc = world * m;  // Imath divides by w
      const double x = world.x, y = world.y - 1.2, z = -world.z;
      EXPECT_NEAR(ndc.x, 0.5 + (v * x / z - c.shiftX) / 36, 1e-5);
      EXPECT_NEAR(ndc.y, 0.5 - (v * y / z - c.shiftY) / 24, 1e-5);
    }
    const cli::RunResult info = cli::runProgram("iinfo", {"-v", out});
    ASSERT_EQ(info.status, 0) << info.err;
    // The number iinfo prints after "key: " (NaN when it is not there).
    const auto printed = [&](const std::string& key) {
      const std::size_t at = info.out.find(key + ": ");
      return at == std::string::npos ? std::nan("")
                                     : std::strtod(info.out.c_str() + at + key.size() + 2, nullptr);
    };
    EXPECT_NEAR(printed("entrancePupilOffset"), v, 1e-3) << info.out;
    EXPECT_NEAR(printed("worldToNDC"), v / 36, 1e-5) << info.out;
  }
}

}  // namespace
}  // namespace lensrt
