// lensrt render writes OpenEXR's standard attributes with their types, so
// that other tools read the camera (aperture, focus, expTime, isoSpeed,
// worldToCamera, chromaticities, capDate), beside the lensrt:* strings.
#include <ImfChromaticitiesAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfInputFile.h>
#include <ImfMatrixAttribute.h>
#include <ImfStandardAttributes.h>
#include <gtest/gtest.h>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::TempDir;

TEST(ExrStandardAttributes, DescribeTheCameraWithTheirTypes) {
  const TempDir dir;
  const std::string out = (dir / "a.exr").string();
  const cli::RunResult r =
      runLensrt({"render", std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf", "--camera", "thin", "--fstop",
                 "5.6", "--focus", "2", "--exposure", "physical", "--shutter", "1/250", "--iso", "400", "--res",
                 "32x18", "--spp", "1", "-q", "-o", out});
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

}  // namespace
}  // namespace lensrt
