// `lensrt render` end to end: determinism across thread counts, one-line
// errors with the right exit status that leave an existing output untouched,
// and every shared sample scene rendering without NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <vector>

#include "cli/cli_util.h"
#include "core/constants.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kCornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";
const std::string kPrecious = "precious bytes that must survive a failed render\n";

TEST(RenderCli, HelpListsEveryOption) {
  const RunResult r = runLensrt({"render", "--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* option :
       {"--output", "--spp", "--res", "--max-depth", "--threads", "--seed", "--camera-node", "--scene-index",
        "--env", "--env-rotate", "--env-intensity", "--film", "--aov", "--quiet"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST(RenderCli, ThreadCountAndTilingDoNotChangeTheImage) {
  const TempDir dir;
  const std::vector<std::string> common{"render", kCornell, "--res", "40x30", "--spp",
                                        "4",      "--seed", "9",     "--aov", "depth,normal,albedo,variance",
                                        "-q"};
  auto run = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = common;
    args.insert(args.end(), extra.begin(), extra.end());
    args.insert(args.end(), {"-o", (dir / out).string()});
    const RunResult r = runLensrt(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return readImage(dir / out);
  };
  const Image a = run("a.exr", {"--threads", "1"});
  const Image b = run("b.exr", {"--threads", "2", "--tile-size", "7"});
  ASSERT_EQ(a.channels, b.channels);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  ASSERT_FALSE(a.pixels.empty());
  EXPECT_EQ(std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)), 0);
  // Not a trivially black image: the Cornell box is lit.
  double sum = 0;
  for (float v : a.pixels) sum += v;
  EXPECT_GT(sum, 0.0);
}

TEST(RenderCli, WritesTheMetadataAndAovChannels) {
  const TempDir dir;
  const RunResult r = runLensrt({"render", kCornell, "--res", "16x16", "--spp", "2", "--seed", "3", "--aov",
                                 "depth,variance", "-q", "-o", (dir / "m.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;  // --quiet
  ImageMetadata meta;
  const Image img = readImage(dir / "m.exr", &meta);
  for (const char* key : {"lensrt:camera", "lensrt:spp", "lensrt:seed", "lensrt:render_seconds",
                          "lensrt:version", "lensrt:command_line", "lensrt:nan_samples"})
    EXPECT_TRUE(meta.count(key)) << key;
  EXPECT_EQ(meta["lensrt:spp"], "2");
  EXPECT_EQ(meta["lensrt:seed"], "3");
  EXPECT_EQ(meta["lensrt:nan_samples"], "0");
  EXPECT_NE(meta["lensrt:camera"].find("pinhole"), std::string::npos);
  for (const char* c : {"R", "G", "B", "A", "depth.Z", "variance.R", "variance.G", "variance.B"})
    EXPECT_GE(img.channelIndex(c), 0) << c;
  EXPECT_LT(img.channelIndex("normal.X"), 0);
  // The camera sits 1.44 m in front of the box's back wall (z = -1.008): the
  // centre pixel sees it at 2.449 m... unless the tall block is there; it is a
  // positive distance in any case and less than the box's diagonal.
  const float depth = img.at(8, 8, img.channelIndex("depth.Z"));
  EXPECT_GT(depth, 0.5f);
  EXPECT_LT(depth, 2.5f);
}

// The camera's placement in the metadata is the glTF camera node's: dof_row's
// camera node is translated to (0, 1.2, 0) with no rotation.
TEST(RenderCli, MetadataNamesWhereTheCameraStood) {
  const TempDir dir;
  const std::string scene = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";
  const RunResult r = runLensrt({"render", scene, "--res", "8x8", "--spp", "1", "--max-depth", "0", "-q",
                                 "-o", (dir / "c.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  ImageMetadata meta;
  readImage(dir / "c.exr", &meta);
  std::istringstream text(meta["lensrt:world_from_camera"]);
  std::vector<double> m;
  for (double v; text >> v;) m.push_back(v);
  ASSERT_EQ(m.size(), 16u) << meta["lensrt:world_from_camera"];
  const double expected[16] = {1, 0, 0, 0, 0, 1, 0, 1.2, 0, 0, 1, 0, 0, 0, 0, 1};
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(m[i], expected[i], 1e-7) << "entry " << i;
}

struct BadInput {
  std::string name;
  std::vector<std::string> args;  // OUT is appended
  int status;
  std::vector<std::string> messageParts;
};

class RenderCliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(RenderCliBadInput, OneLineErrorExitStatusAndOutputUntouched) {
  const TempDir dir;
  const BadInput& c = GetParam();
  // Inputs the case refers to by name.
  const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const float nanTri[9] = {0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 1, 0};
  cli::writeFile(dir / "broken.gltf", R"({"asset": {"version": "2.0"}, "scenes": [ )");
  cli::writeFile(dir / "short.gltf", cli::triangleGltf(tri, {0, 1, 2}, 24));
  cli::writeFile(dir / "badindex.gltf", cli::triangleGltf(tri, {0, 1, 7}));
  cli::writeFile(dir / "nan.gltf", cli::triangleGltf(nanTri, {0, 1, 2}));
  cli::writeFile(dir / "good.gltf", cli::triangleGltf(tri, {0, 1, 2}));
  const auto out = dir / "out.exr";
  cli::writeFile(out, kPrecious);

  std::vector<std::string> args{"render"};
  for (const std::string& a : c.args) args.push_back(a.rfind("@", 0) == 0 ? (dir / a.substr(1)).string() : a);
  args.insert(args.end(), {"-o", out.string()});
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, c.status) << r.err;
  const std::vector<std::string> errLines = cli::lines(r.err);
  ASSERT_EQ(errLines.size(), 1u) << r.err;
  EXPECT_EQ(errLines[0].rfind("lensrt: error: ", 0), 0u) << r.err;
  for (const std::string& part : c.messageParts) EXPECT_NE(r.err.find(part), std::string::npos) << r.err;
  EXPECT_EQ(cli::readFile(out), kPrecious);
  // No temporary file left behind either.
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 6);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, RenderCliBadInput,
    ::testing::Values(
        BadInput{"MissingFile", {"@missing.gltf"}, 1, {"missing.gltf", "not found"}},
        BadInput{"BrokenJson", {"@broken.gltf"}, 1, {"broken.gltf"}},
        BadInput{"BufferTooShort", {"@short.gltf"}, 1, {"short.gltf"}},
        BadInput{"IndexOutOfRange", {"@badindex.gltf"}, 1, {"badindex.gltf", "index"}},
        BadInput{"NanVertex", {"@nan.gltf"}, 1, {"nan.gltf", "NaN"}},
        BadInput{"UnknownFlag", {"@good.gltf", "--bogus"}, 2, {"--bogus"}},
        BadInput{"ZeroSpp", {"@good.gltf", "--spp", "0"}, 2, {"--spp"}},
        BadInput{"BadResSyntax", {"@good.gltf", "--res", "640by360"}, 2, {"--res"}},
        BadInput{"ZeroRes", {"@good.gltf", "--res", "0x360"}, 2, {"--res"}},
        BadInput{"NegativeEnv", {"@good.gltf", "--env", "constant:-1"}, 2, {"--env"}},
        BadInput{"MissingEnvMap", {"@good.gltf", "--env", "@nowhere.exr"}, 1, {"nowhere.exr"}},
        BadInput{"UnknownAov", {"@good.gltf", "--aov", "depth,colour"}, 2, {"--aov"}},
        BadInput{"UnknownLightSampler",
                 {"@good.gltf", "--light-sampler", "bvh"},
                 2,
                 {"--light-sampler", "expected tree or power", "'bvh'"}},
        // Asking for what the file does not have is a wrong flag value: exit 2, naming flag and file.
        BadInput{"UnknownCamera",
                 {"@good.gltf", "--camera-node", "nosuchcam"},
                 2,
                 {"--camera-node", "good.gltf", "nosuchcam"}},
        BadInput{
            "SceneIndexOutOfRange", {"@good.gltf", "--scene-index", "5"}, 2, {"--scene-index", "good.gltf"}},
        BadInput{"SppNotANumber", {"@good.gltf", "--spp", "abc"}, 2, {"--spp", "positive integer", "'abc'"}},
        BadInput{
            "ZeroNoiseThreshold", {"@good.gltf", "--noise-threshold", "0"}, 2, {"--noise-threshold", "> 0"}},
        BadInput{
            "NegativeNoiseThreshold", {"@good.gltf", "--noise-threshold", "-0.01"}, 2, {"--noise-threshold"}},
        BadInput{"NoiseThresholdNotANumber",
                 {"@good.gltf", "--noise-threshold", "low"},
                 2,
                 {"--noise-threshold", "'low'"}},
        BadInput{"NoiseThresholdNaN", {"@good.gltf", "--noise-threshold", "nan"}, 2, {"--noise-threshold"}},
        BadInput{"MinSppAboveSpp",
                 {"@good.gltf", "--noise-threshold", "0.01", "--spp", "8", "--min-spp", "16"},
                 2,
                 {"--min-spp", "16 is above --spp 8"}},
        BadInput{
            "ZeroMinSpp", {"@good.gltf", "--noise-threshold", "0.01", "--min-spp", "0"}, 2, {"--min-spp"}},
        BadInput{"MinSppWithoutThreshold",
                 {"@good.gltf", "--min-spp", "4"},
                 2,
                 {"--min-spp", "--noise-threshold"}}),
    [](const auto& info) { return info.param.name; });

TEST(RenderCli, UnwritableOutputIsRejectedBeforeRendering) {
  const TempDir dir;
  cli::writeFile(dir / "keep.txt", kPrecious);
  const RunResult noDir = runLensrt({"render", kCornell, "-q", "-o", (dir / "keep.txt/dir/a.exr").string()});
  EXPECT_EQ(noDir.status, 1);
  EXPECT_NE(noDir.err.find("cannot create the folder"), std::string::npos) << noDir.err;
  const RunResult badExt = runLensrt({"render", kCornell, "-q", "-o", (dir / "keep.txt").string()});
  EXPECT_EQ(badExt.status, 2);
  EXPECT_NE(badExt.err.find("extension"), std::string::npos) << badExt.err;
  EXPECT_EQ(cli::readFile(dir / "keep.txt"), kPrecious);
}

TEST(RenderCli, LatLongEnvironmentMapLightsTheScene) {
  const TempDir dir;
  // A uniform sky of radiance 2 as a lat-long EXR: every background pixel must
  // read 2 (the pinhole's default film records radiance), and a white-ish
  // triangle lit only by it must be lit.
  Image sky(16, 8, {"R", "G", "B"});
  for (float& v : sky.pixels) v = 2.0f;
  writeImage(dir / "sky.exr", sky, {});
  cli::writeFile(dir / "bad.exr", "not an image");
  const float tri[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
  cli::writeFile(dir / "tri.gltf", cli::triangleGltf(tri, {0, 1, 2}));
  // RGB transport carries the map's 2 exactly (spectral transport adds colour noise).
  const RunResult ok =
      runLensrt({"render", (dir / "tri.gltf").string(), "--res", "24x24", "--spp", "2", "--spectral", "off",
                 "--env", (dir / "sky.exr").string(), "-q", "-o", (dir / "a.exr").string()});
  ASSERT_EQ(ok.status, 0) << ok.err;
  const Image img = readImage(dir / "a.exr");
  const int r = img.channelIndex("R"), a = img.channelIndex("A");
  int background = 0, lit = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      if (img.at(x, y, a) == 0.0f) {
        EXPECT_NEAR(img.at(x, y, r), 2.0, 1e-5) << x << "," << y;
        ++background;
      } else if (img.at(x, y, a) == 1.0f && img.at(x, y, r) > 0.1f) {
        ++lit;
      }
    }
  EXPECT_GT(background, 0);
  EXPECT_GT(lit, 0);
  const RunResult bad = runLensrt({"render", (dir / "tri.gltf").string(), "--env", (dir / "bad.exr").string(),
                                   "-q", "-o", (dir / "b.exr").string()});
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("bad.exr"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.exr"));
}

// Optional: the Khronos samples in ../shared (skipped when absent).
TEST(RenderCli, EverySharedSampleSceneRendersWithoutNaN) {
  const std::filesystem::path scenes = std::filesystem::path(LENSRT_SHARED_DIR) / "scenes";
  if (!std::filesystem::is_directory(scenes)) GTEST_SKIP() << "no shared scenes at " << scenes;
  const TempDir dir;
  int rendered = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(scenes)) {
    const std::string ext = e.path().extension().string();
    if (ext != ".gltf" && ext != ".glb") continue;
    const auto out = dir / "s.exr";
    const RunResult r = runLensrt({"render", e.path().string(), "--res", "32x32", "--spp", "1", "--env",
                                   "constant:0.5", "-q", "-o", out.string()});
    ASSERT_EQ(r.status, 0) << e.path() << ": " << r.err;
    ImageMetadata meta;
    const Image img = readImage(out, &meta);
    EXPECT_EQ(meta["lensrt:nan_samples"], "0") << e.path();
    for (float v : img.pixels) ASSERT_TRUE(std::isfinite(v)) << e.path();
    ++rendered;
  }
  EXPECT_GT(rendered, 0);
}

}  // namespace
}  // namespace lensrt
