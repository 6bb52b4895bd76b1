// `lensrt render`'s environment: the default sky for a scene with no light
// source (with its notice), --env-intensity, and --env-rotate's documented
// sign (about +Y by the right-hand rule: +90 degrees brings what the map shows
// at +X to the front, -Z).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

constexpr float kTriangle[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};

// R at the top-left pixel, which sees the sky (checked: A == 0) a little to
// the left of and above -Z. The renders use RGB transport (--spectral off),
// which carries the sky's value exactly; spectral transport adds colour noise.
float skyPixel(const std::filesystem::path& file) {
  const Image img = readImage(file);
  EXPECT_EQ(img.at(1, 1, img.channelIndex("A")), 0.0f) << "the pixel sees the sky";
  return img.at(1, 1, img.channelIndex("R"));
}

TEST(EnvironmentCli, ASceneWithoutLightsGetsTheDefaultSkyWithANotice) {
  const TempDir dir;
  cli::writeFile(dir / "tri.gltf", cli::triangleGltf(kTriangle, {0, 1, 2}));
  const std::vector<std::string> common{
      "render", (dir / "tri.gltf").string(), "--res", "24x24", "--spp", "2", "--spectral", "off"};
  auto run = [&](std::vector<std::string> extra, const std::string& out) {
    std::vector<std::string> args = common;
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"-o", (dir / out).string()});
    return runLensrt(args);
  };
  const RunResult plain = run({}, "a.exr");
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_NE(
      plain.err.find("lensrt: warning: " + (dir / "tri.gltf").string() +
                     ": the scene has no light source: lighting it with the default environment, a uniform "
                     "sky of radiance 1 (--env chooses another)\n"),
      std::string::npos)
      << plain.err;
  EXPECT_EQ(skyPixel(dir / "a.exr"), 1.0f);

  const RunResult half = run({"--env-intensity", "0.5"}, "b.exr");
  ASSERT_EQ(half.status, 0) << half.err;
  EXPECT_NE(half.err.find("a uniform sky of radiance 0.5"), std::string::npos) << half.err;
  EXPECT_EQ(skyPixel(dir / "b.exr"), 0.5f);

  // --env-intensity scales a constant --env too; an explicit black one stays black.
  const RunResult scaled = run({"--env", "constant:2", "--env-intensity", "1.5", "-q"}, "c.exr");
  ASSERT_EQ(scaled.status, 0) << scaled.err;
  EXPECT_EQ(skyPixel(dir / "c.exr"), 3.0f);
  const RunResult black = run({"--env", "constant:0"}, "d.exr");
  ASSERT_EQ(black.status, 0) << black.err;
  EXPECT_NE(black.err.find("the image will be black"), std::string::npos) << black.err;
  EXPECT_EQ(black.err.find("default environment"), std::string::npos) << black.err;
  EXPECT_EQ(skyPixel(dir / "d.exr"), 0.0f);
}

TEST(EnvironmentCli, RotationTurnsTheMapCounterclockwiseSeenFromAbove) {
  const TempDir dir;
  cli::writeFile(dir / "tri.gltf", cli::triangleGltf(kTriangle, {0, 1, 2}));
  // Each quarter of azimuth in its own value: -Z 1, +X 2, +Z 3, -X 4 (column
  // u = 0.5 looks down -Z and u grows toward +X).
  Image sky(16, 8, {"R", "G", "B"});
  for (int y = 0; y < sky.height; ++y)
    for (int x = 0; x < sky.width; ++x) {
      const float v = x >= 6 && x <= 9 ? 1.0f : x >= 10 && x <= 13 ? 2.0f : x >= 2 && x <= 5 ? 4.0f : 3.0f;
      for (int c = 0; c < 3; ++c) sky.at(x, y, c) = v;
    }
  writeImage(dir / "sky.exr", sky, {});
  for (const auto& [degrees, expected] :
       std::vector<std::pair<std::string, float>>{{"0", 1.0f}, {"90", 2.0f}, {"180", 3.0f}, {"-90", 4.0f}}) {
    SCOPED_TRACE(degrees);
    const RunResult r = runLensrt({"render", (dir / "tri.gltf").string(), "--res", "24x24", "--spp", "1",
                                   "--spectral", "off", "--env", (dir / "sky.exr").string(), "--env-rotate",
                                   degrees, "-q", "-o", (dir / "r.exr").string()});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(skyPixel(dir / "r.exr"), expected);
  }
}

TEST(EnvironmentCli, BadValuesAreUsageErrors) {
  const TempDir dir;
  cli::writeFile(dir / "tri.gltf", cli::triangleGltf(kTriangle, {0, 1, 2}));
  for (const auto& [flag, value] :
       std::vector<std::pair<std::string, std::string>>{{"--env-rotate", "left"},
                                                        {"--env-rotate", "inf"},
                                                        {"--env-rotate", "400"},
                                                        {"--env-intensity", "-1"},
                                                        {"--env-intensity", "nan"},
                                                        {"--env-intensity", ""}}) {
    SCOPED_TRACE(flag + " " + value);
    const RunResult r =
        runLensrt({"render", (dir / "tri.gltf").string(), flag, value, "-o", (dir / "x.exr").string()});
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
    EXPECT_EQ(r.err.rfind("lensrt: error: " + flag, 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
  }
}

}  // namespace
}  // namespace lensrt
