// `lensrt diff` end to end: exit statuses and JSON figures.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "image_test_util.h"

namespace lensrt {
namespace {

using test::runCommand;
using test::shellQuote;

std::string diffCommand(const std::string& args) {
  return shellQuote(LENSRT_BINARY) + " diff " + args + " 2>/dev/null";
}

struct DiffCommand : ::testing::Test {
  test::ScratchDir dir;
  std::string a, b;
  void SetUp() override {
    a = (dir / "a.exr").string();
    b = (dir / "b.exr").string();
    Image image = test::constantImage(8, 6, {"R", "G", "B"}, 0.5f);
    writeImage(a, image, {});
    image.at(2, 3, 0) = 0.51f;  // one value off by 0.01
    writeImage(b, image, {});
  }
  int status(const std::string& args) { return runCommand(diffCommand(args)).status; }
};

TEST_F(DiffCommand, ExitStatusesFollowIdiff) {
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(a)), 0);
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(b) + " --fail 0.1 --warn 0.001"), 1);
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(b)), 2);
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(b) + " --fail-percent 2.5 --warn-percent 2.5"), 0);
}

// The thresholds whose default is inf take inf (the README's example spells
// the defaults out); a bad value's message names the range in a few digits.
TEST_F(DiffCommand, ThresholdsTakeInfAndNameTheirRangeBriefly) {
  const std::string ab = shellQuote(a) + " " + shellQuote(b);
  for (const char* v : {"inf", "infinity", "Inf"}) {
    EXPECT_EQ(status(ab + " --fail 0.1 --warn 0.1 --hard-fail " + v + " --hard-warn " + v), 0) << v;
    // --hard-fail inf cannot fail; a finite one below the error does.
  }
  EXPECT_EQ(status(ab + " --fail 0.1 --hard-fail 0.001"), 2);
  const auto bad = runCommand(shellQuote(LENSRT_BINARY) + " diff " + ab + " --hard-fail -1 2>&1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.output.find("--hard-fail: expected a number >= 0 or inf"), std::string::npos) << bad.output;
  EXPECT_LT(bad.output.size(), 200u) << bad.output;
  const auto notInf = runCommand(shellQuote(LENSRT_BINARY) + " diff " + ab + " --fail inf 2>&1");
  EXPECT_EQ(notInf.status, 2) << notInf.output;  // --fail's default is finite: no inf
  EXPECT_NE(notInf.output.find("--fail: expected a number >= 0 (|A-B|), got 'inf'"), std::string::npos)
      << notInf.output;
}

TEST_F(DiffCommand, IncomparableAndUnreadable) {
  const std::string small = (dir / "small.exr").string();
  writeImage(small, test::constantImage(4, 6, {"R", "G", "B"}, 0.5f), {});
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(small)), 3);
  // Refusals still give a JSON document with --json.
  const auto missing =
      runCommand(diffCommand(shellQuote(a) + " " + shellQuote((dir / "missing.exr").string()) + " --json"));
  EXPECT_EQ(missing.status, 4);
  const auto j = nlohmann::json::parse(missing.output);
  EXPECT_EQ(j["exitStatus"], 4);
  EXPECT_NE(j["error"].get<std::string>().find("missing.exr"), std::string::npos);
}

TEST_F(DiffCommand, JsonCarriesTheFigures) {
  const auto result = runCommand(diffCommand(shellQuote(a) + " " + shellQuote(b) + " --json"));
  EXPECT_EQ(result.status, 2);
  const auto j = nlohmann::json::parse(result.output);
  const double d = double(0.51f) - double(0.5f);
  EXPECT_NEAR(j["overall"]["maxError"].get<double>(), d, 1e-9);
  EXPECT_EQ(j["overall"]["maxPixel"], nlohmann::json({2, 3}));
  EXPECT_EQ(j["overall"]["maxChannel"], "R");
  EXPECT_NEAR(j["overall"]["rmse"].get<double>(), std::sqrt(d * d / 144), 1e-9);
  EXPECT_EQ(j["overall"]["failCount"], 1);
  EXPECT_EQ(j["verdict"], "FAILURE");
  EXPECT_TRUE(j["channels"][1]["psnr"].is_null());  // identical channel: infinite PSNR
}

TEST_F(DiffCommand, HeatmapIsWritten) {
  const auto heat = dir / "heat.png";
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(b) + " --heatmap " + shellQuote(heat.string())), 2);
  const Image map = readImage(heat);
  EXPECT_GT(map.width, 8);
  EXPECT_EQ(map.channelCount(), 3u);
}

TEST_F(DiffCommand, NoiseAwareSeedsPassGainFails) {
  const auto write = [&](const std::string& name, unsigned seed, double gain) {
    const std::string path = (dir / name).string();
    writeImage(path, test::noisyRender(64, 64, seed, 64, 0.25, gain), {{"lensrt:spp", "64"}});
    return shellQuote(path);
  };
  const std::string s1 = write("s1.exr", 1, 1.0), s2 = write("s2.exr", 2, 1.0), g = write("g.exr", 3, 1.02);
  EXPECT_EQ(status(s1 + " " + g + " --noise-aware"), 2);
  const auto result = runCommand(diffCommand(s1 + " " + s2 + " --noise-aware --json"));
  EXPECT_EQ(result.status, 0);
  const auto j = nlohmann::json::parse(result.output);
  EXPECT_EQ(j["noiseAware"]["degreesOfFreedom"], 63);  // from the lensrt:spp metadata
  // Plain images have no variance: not comparable noise-aware.
  EXPECT_EQ(status(shellQuote(a) + " " + shellQuote(b) + " --noise-aware"), 3);
}

}  // namespace
}  // namespace lensrt
