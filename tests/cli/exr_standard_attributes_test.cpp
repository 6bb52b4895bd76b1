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
#include <string>

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

}  // namespace
}  // namespace lensrt
