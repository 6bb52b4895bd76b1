// --ocio-display/--ocio-view: a preview through OpenColorIO's display
// transform (from the $OCIO config's scene_linear role), against a small
// config whose views are the sRGB curve, a 2.2 gamma and no transform; and
// the one-line usage errors before rendering.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"
#include "oiio_plugin_for_tests.h"

namespace lensrt {
namespace {

using cli::RunResult;
using cli::TempDir;

constexpr const char* kConfig = R"(ocio_profile_version: 2

roles:
  default: linear
  scene_linear: linear

displays:
  sRGB:
    - !<View> {name: Standard, colorspace: srgb_display}
    - !<View> {name: Gamma22, colorspace: gamma22_display}
    - !<View> {name: Raw, colorspace: linear}

colorspaces:
  - !<ColorSpace>
    name: linear
  - !<ColorSpace>
    name: srgb_display
    to_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055}
  - !<ColorSpace>
    name: gamma22_display
    to_scene_reference: !<ExponentTransform> {value: 2.2}
)";

// A flat field of radiance 0.25 to `out`, with $OCIO set to `config` (empty:
// unset) and `flags` added.
RunResult renderFlat(const TempDir& dir, const std::string& out, const std::string& config,
                     const std::vector<std::string>& flags) {
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  std::vector<std::string> args =
      config.empty() ? std::vector<std::string>{"-u", "OCIO"} : std::vector<std::string>{"OCIO=" + config};
  for (const std::string& a :
       {std::string(LENSRT_BINARY), std::string("render"), (dir / "sky.gltf").string(), std::string("--env"),
        std::string("constant:0.25"), std::string("--res"), std::string("40x34"), std::string("--spp"),
        std::string("1"), std::string("--spectral"), std::string("off"),  // the sky's value exactly
        std::string("-q"), std::string("-o"), (dir / out).string()})
    args.push_back(a);
  args.insert(args.end(), flags.begin(), flags.end());
  return cli::runProgram("env", args);
}

TEST(OcioDisplayCli, TheConfigsViewsShapeThePreview) {
  if (!test::useBuiltOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  cli::writeFile(dir / "config.ocio", kConfig);
  const std::string config = (dir / "config.ocio").string();
  ASSERT_EQ(renderFlat(dir, "plain.tif", "", {}).status, 0);
  struct Case {
    const char* view;
    double expected;  // the 16-bit code of 0.25 through the view
  };
  const double plain = readImage(dir / "plain.tif").at(20, 17, 0) * 65535;
  for (const Case& c : {Case{"Standard", plain}, Case{"Gamma22", std::round(std::pow(0.25, 1 / 2.2) * 65535)},
                        Case{"Raw", std::round(0.25 * 65535)}}) {
    SCOPED_TRACE(c.view);
    const std::string out = std::string(c.view) + ".tif";
    const RunResult r = renderFlat(dir, out, config, {"--ocio-display", "sRGB", "--ocio-view", c.view});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NEAR(readImage(dir / out).at(20, 17, 1) * 65535, c.expected, 0.01);
  }
  // The default display and view (sRGB, Standard): the sRGB curve, as without them.
  const RunResult r = renderFlat(dir, "default.png", config, {"--ocio-view", "Standard"});
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(renderFlat(dir, "plain.png", "", {}).status, 0);
  EXPECT_EQ(readImage(dir / "default.png").pixels, readImage(dir / "plain.png").pixels);
}

TEST(OcioDisplayCli, ProblemsAreOneUsageLineBeforeRendering) {
  if (!test::builtOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  cli::writeFile(dir / "config.ocio", kConfig);
  const std::string config = (dir / "config.ocio").string();
  RunResult r = renderFlat(dir, "a.png", config, {"--ocio-display", "sRGB", "--ocio-view", "Film"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(
      r.err,
      "lensrt: error: --ocio-display: display 'sRGB' has no view 'Film' (displays and their views: sRGB: "
      "Standard, Gamma22, Raw)\n");
  r = renderFlat(dir, "a.png", "", {"--ocio-display", "sRGB"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(
      r.err,
      "lensrt: error: --ocio-display: the OpenColorIO config has no displays ($OCIO names the config file, "
      "e.g. an ACES config)\n");
  r = renderFlat(dir, "a.exr", config, {"--ocio-display", "sRGB"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(
      r.err,
      "lensrt: error: --ocio-display: applies to previews (.png, .jpg, .tif, .jp2, .webp), not .exr files "
      "(scene-linear or log)\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  EXPECT_FALSE(std::filesystem::exists(dir / "a.exr"));
}

}  // namespace
}  // namespace lensrt
