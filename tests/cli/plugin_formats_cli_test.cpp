// The formats lensrt writes and reads through its OpenImageIO plugin, end to
// end: a render to each (.tif, .dpx, .jp2, .webp) checked by OpenImageIO's
// own oiiotool and read back through lensrt; environment maps in them; the
// one-line errors when the plugin or OpenImageIO is missing; and lensrt
// itself never linking OpenImageIO (its start-up stays fast).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/cineon.h"
#include "image/image_io.h"
#include "image/srgb.h"
#include "oiio_plugin_for_tests.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
using cli::RunResult;
using cli::TempDir;

// A flat field: every pixel sees the constant sky, so every pixel is `radiance`
// (RGB transport carries it exactly; spectral transport adds colour noise).
RunResult renderFlat(const TempDir& dir, const std::string& out, const std::string& env = "constant:0.25",
                     const std::string& res = "40x34") {
  if (!fs::exists(dir / "sky.gltf")) cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  return cli::runLensrt({"render", (dir / "sky.gltf").string(), "--env", env, "--res", res, "--spp", "1",
                         "--spectral", "off", "-q", "-o", (dir / out).string()});
}

// lensrt under another LENSRT_OIIO_PLUGIN.
RunResult runWithPlugin(const std::string& plugin, const std::vector<std::string>& args) {
  std::vector<std::string> envArgs{"LENSRT_OIIO_PLUGIN=" + plugin, LENSRT_BINARY};
  envArgs.insert(envArgs.end(), args.begin(), args.end());
  return cli::runProgram("env", envArgs);
}

// What OpenImageIO's tools say of a file: iinfo's line ("F : 40 x 34, 3
// channel, uint16 tiff") and oiiotool's mean code of the first channel and
// largest code.
struct OiioInfo {
  std::string header;
  double mean = -1, full = -1;
};

OiioInfo oiioStats(const fs::path& file) {
  OiioInfo info;
  const RunResult i = cli::runProgram("iinfo", {file.string()});
  EXPECT_EQ(i.status, 0) << i.err;
  for (const char c : i.out)  // "F :   40 x   34, ..." with the runs of spaces as one
    if (c != ' ' || info.header.empty() || info.header.back() != ' ') info.header += c;
  const RunResult r = cli::runProgram("oiiotool", {file.string(), "--printstats"});
  EXPECT_EQ(r.status, 0) << r.err;
  for (const std::string& line : cli::lines(r.out)) {
    if (const std::size_t at = line.find("Stats Avg: "); at != std::string::npos) {
      std::istringstream in(line.substr(at + 11));
      in >> info.mean;
      const std::size_t of = line.find("(of ");
      if (of != std::string::npos) info.full = std::stod(line.substr(of + 4));
    }
  }
  return info;
}

TEST(PluginFormatsCli, RendersToEachFormatAndReadsItBack) {
  if (!test::builtOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  struct Case {
    const char* file;
    const char* type;  // as oiiotool names it
    double full, code, tolerance;
  };
  const double srgb = srgbEncode(0.25f);
  const Case cases[] = {{"out.tif", "uint16 tiff", 65535, std::round(srgb * 65535), 0},
                        {"out.jp2", "uint16 jpeg2000", 65535, std::round(srgb * 65535), 0},
                        {"out.webp", "uint8 webp", 255, std::round(srgb * 255), 1},
                        {"out.dpx", "uint10 dpx", 1023, std::round(cineonEncode(0.25f)), 0}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const RunResult r = renderFlat(dir, c.file);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const OiioInfo info = oiioStats(dir / c.file);
    EXPECT_NE(info.header.find(": 40 x 34, 3 channel, " + std::string(c.type)), std::string::npos)
        << info.header;
    EXPECT_EQ(info.full, c.full);
    EXPECT_NEAR(info.mean, c.code, c.tolerance + 0.02);  // oiiotool goes through 16 bits
  }
  // Read back through lensrt's plugin, as stored codes and as light.
  test::useBuiltOiioPlugin();
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    const Image stored = readImage(dir / c.file);
    ASSERT_EQ(stored.width, 40);
    ASSERT_EQ(stored.height, 34);
    EXPECT_NEAR(stored.at(20, 17, 0) * c.full, c.code, c.tolerance + 0.01);
    EXPECT_NEAR(readLinearImage(dir / c.file).at(20, 17, 0), 0.25, 0.25 * 0.01);
  }
}

TEST(PluginFormatsCli, EnvironmentMapsInTiffWebPDpxAndJpeg2000LightTheScene) {
  if (!test::builtOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  // The sky's radiance, 0.25, stored in each format (display-referred files
  // store it under the sRGB curve, DPX in Cineon log), lights a flat field
  // with 0.25 again once read back as linear light.
  for (const char* map : {"sky.tif", "sky.webp", "sky.dpx", "sky.jp2"}) {
    SCOPED_TRACE(map);
    ASSERT_EQ(renderFlat(dir, map, "constant:0.25", "64x32").status, 0);
    const RunResult r = renderFlat(dir, "lit.exr", (dir / map).string(), "16x16");
    ASSERT_EQ(r.status, 0) << r.err;
    const Image lit = readImage(dir / "lit.exr");
    const int g = lit.channelIndex("G");
    for (const int x : {0, 8, 15}) EXPECT_NEAR(lit.at(x, 8, g), 0.25, 0.25 * 0.01) << x;
  }
}

TEST(PluginFormatsCli, AMissingPluginIsOneLineBeforeAnythingIsRendered) {
  if (!test::builtOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  ASSERT_EQ(renderFlat(dir, "sky.webp").status, 0);
  cli::writeFile(dir / "out.tif", "an earlier render");
  const std::string missing = (dir / "nowhere" / "lensrt_oiio.so").string();
  const std::string scene = (dir / "sky.gltf").string();
  RunResult r =
      runWithPlugin(missing, {"render", scene, "--env", "constant:1", "-o", (dir / "out.tif").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "lensrt: error: " + (dir / "out.tif").string() +
                       ": writing TIFF files needs lensrt's OpenImageIO plugin: LENSRT_OIIO_PLUGIN names " +
                       missing + ", which does not exist\n");
  EXPECT_EQ(cli::readFile(dir / "out.tif"), "an earlier render");
  r = runWithPlugin(
      missing, {"render", scene, "--env", (dir / "sky.webp").string(), "-o", (dir / "lit.exr").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "lensrt: error: " + (dir / "sky.webp").string() +
                       ": reading WebP images needs lensrt's OpenImageIO plugin: LENSRT_OIIO_PLUGIN names " +
                       missing + ", which does not exist\n");
  // lensrt's own formats need no plugin.
  for (const char* own : {"own.exr", "own.png", "own.jpg"}) {
    r = runWithPlugin(missing, {"render", scene, "--env", "constant:1", "--res", "8x8", "--spp", "1", "-q",
                                "-o", (dir / own).string()});
    EXPECT_EQ(r.status, 0) << own << ": " << r.err;
  }
}

// The plugin with its OpenImageIO dependency renamed to a version that is
// not installed: what a machine without OpenImageIO sees.
TEST(PluginFormatsCli, AMissingOpenImageIOIsOneLineThatSaysSo) {
  if (!test::builtOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  std::string plugin = cli::readFile(LENSRT_OIIO_PLUGIN_FILE);
  const std::string needed = "libOpenImageIO.so.";
  const std::size_t at = plugin.find(needed);
  ASSERT_NE(at, std::string::npos);
  for (std::size_t i = at + needed.size(); i < plugin.size() && plugin[i] != '\0'; ++i)
    if (plugin[i] != '.') plugin[i] = '9';
  const std::string renamed = plugin.substr(at, plugin.find('\0', at) - at);
  cli::writeFile(dir / "lensrt_oiio.so", plugin);
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  const RunResult r = runWithPlugin((dir / "lensrt_oiio.so").string(), {"render", (dir / "sky.gltf").string(),
                                                                        "-o", (dir / "out.dpx").string()});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "lensrt: error: " + (dir / "out.dpx").string() +
                       ": writing DPX files needs lensrt's OpenImageIO plugin: " +
                       (dir / "lensrt_oiio.so").string() + " cannot be loaded: " + renamed +
                       ": cannot open shared object file: No such file or directory (OpenImageIO is not "
                       "installed: on Debian, apt-get install libopenimageio2.4)\n");
}

TEST(PluginFormatsCli, Jpeg2000BelowThirtyTwoPixelsIsOneLineAndNoFile) {
  if (!test::builtOiioPlugin()) GTEST_SKIP() << "built without OpenImageIO";
  const TempDir dir;
  const RunResult r = renderFlat(dir, "small.jp2", "constant:0.25", "16x16");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "lensrt: error: " + (dir / "small.jp2").string() +
                       ": cannot write: a JPEG 2000 image needs at least 32x32 pixels\n");
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir.path())) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"sky.gltf"});
}

// lensrt --version stays fast (under 50 ms and 30 MB in the README's
// measurement) because the command never links OpenImageIO.
TEST(PluginFormatsCli, TheCommandDoesNotLinkOpenImageIO) {
  const RunResult r = cli::runProgram("ldd", {LENSRT_BINARY});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("OpenImageIO"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("OpenColorIO"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace lensrt
