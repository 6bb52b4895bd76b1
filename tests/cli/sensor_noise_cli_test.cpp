// lensrt render --noise on: the image a sensor reads out, with the render
// kept as noiseless.R/G/B; the reading is the same whole or in tiles (merged),
// and a tile rendered without noise does not merge with one rendered with it.
// The physics (photon transfer curve) is tests/python/test_sensor_noise.py's.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kScene = std::string(LENSRT_SOURCE_DIR) + "/scenes/flat_wall.gltf";

std::vector<std::string> renderArgs(const std::filesystem::path& out, std::vector<std::string> extra) {
  std::vector<std::string> args = {"render", kScene, "--camera", "thin", "--focal-length", "50", "--fstop",
                                   "4", "--res", "40x30", "--spp", "2", "--env", "none", "--noise", "on",
                                   "--sensor-params", "smartphone",
                                   // RGB transport: no colour noise, and no negative values in the
                                   // render (spectral sRGB has them at low spp; the sensor clips them).
                                   "--spectral", "off", "-q", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

TEST(SensorNoiseCli, ReadsOutTheRenderAndKeepsItAsNoiseless) {
  const TempDir dir;
  const RunResult r = runLensrt(renderArgs(dir / "a.exr", {}));
  ASSERT_EQ(r.status, 0) << r.err;
  ImageMetadata meta;
  const Image img = readImage(dir / "a.exr", &meta);
  ASSERT_GE(img.channelIndex("noiseless.G"), 0);
  EXPECT_NE(meta["lensrt:sensor_noise"].find("smartphone: full well 6000 e"), std::string::npos);
  EXPECT_NE(meta["lensrt:settings"].find("sensor_noise=smartphone"), std::string::npos);
  // Normalized exposure: 1.0 fills the 6000 e well, so the reading differs
  // from the render by about sqrt(6000 v) / 6000 (shot noise), never by more
  // than the clipping allows.
  const int g = img.channelIndex("G"), n = img.channelIndex("noiseless.G");
  double sum = 0, sumSq = 0, meanValue = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const double d = img.at(x, y, g) - img.at(x, y, n);
      sum += d, sumSq += d * d, meanValue += img.at(x, y, n);
    }
  const double count = img.width * img.height, mean = sum / count, var = sumSq / count - mean * mean;
  meanValue /= count;
  EXPECT_NEAR(mean, 0.0, 4 * std::sqrt(var / count));
  // Shot noise in value units: v / 6000; more from read noise, PRNU and quantisation.
  EXPECT_GT(var, 0.9 * meanValue / 6000.0);
  EXPECT_LT(var, 2.0 * meanValue / 6000.0);
}

TEST(SensorNoiseCli, TilesReadOutTheWholeFramesNumbers) {
  const TempDir dir;
  ASSERT_EQ(runLensrt(renderArgs(dir / "whole.exr", {})).status, 0);
  for (const char* tile : {"0/2", "1/2"})
    ASSERT_EQ(runLensrt(renderArgs(dir / (std::string("t") + tile[0] + ".exr"), {"--tile", tile})).status, 0);
  const RunResult merged = runLensrt(
      {"merge", (dir / "t0.exr").string(), (dir / "t1.exr").string(), "-o", (dir / "m.exr").string()});
  ASSERT_EQ(merged.status, 0) << merged.err;
  const RunResult same =
      runLensrt({"diff", (dir / "whole.exr").string(), (dir / "m.exr").string(), "--fail", "0"});
  EXPECT_EQ(same.status, 0) << same.out;
  // A noiseless tile is another render.
  std::vector<std::string> plain = renderArgs(dir / "p1.exr", {"--tile", "1/2"});
  plain.erase(plain.begin() + 14, plain.begin() + 18);  // --noise on --sensor-params smartphone
  ASSERT_EQ(runLensrt(plain).status, 0);
  const RunResult mixed = runLensrt(
      {"merge", (dir / "t0.exr").string(), (dir / "p1.exr").string(), "-o", (dir / "x.exr").string()});
  EXPECT_NE(mixed.status, 0);
  EXPECT_NE(mixed.err.find("settings"), std::string::npos) << mixed.err;
}

// `lensrt sensor list --json` prints each preset as a sensor file holds it
// (in "sensor_params"): written out and given back, it reads out the preset's
// very numbers.
TEST(SensorNoiseCli, ListedPresetsAreSensorFiles) {
  const TempDir dir;
  const RunResult list = runLensrt({"sensor", "list", "--json"});
  ASSERT_EQ(list.status, 0) << list.err;
  const RunResult text = runLensrt({"sensor", "list"});
  for (const char* name : {"default", "full-frame", "smartphone", "machine-vision"})
    EXPECT_NE(text.out.find(name), std::string::npos) << name;
  const nlohmann::json presets = nlohmann::json::parse(list.out).at("sensor_params");
  ASSERT_EQ(presets.size(), 4u);
  const nlohmann::json& one = presets[2];
  ASSERT_EQ(one.at("name"), "smartphone") << one;
  cli::writeFile(dir / "phone.json", one.dump(2));
  std::vector<std::string> fromFile = renderArgs(dir / "file.exr", {});
  fromFile[17] = (dir / "phone.json").string();
  ASSERT_EQ(runLensrt(fromFile).status, 0);
  ASSERT_EQ(runLensrt(renderArgs(dir / "preset.exr", {})).status, 0);
  const RunResult same =
      runLensrt({"diff", (dir / "file.exr").string(), (dir / "preset.exr").string(), "--fail", "0"});
  EXPECT_EQ(same.status, 0) << same.out;
}

// Physical exposure on the default 36 x 24 mm sensor at 90 x 60 pixels: 400
// um pixels collect 2.55e8 electrons at an image value of 1 (78 / ISO 100 lux
// s x 4.09e15 photons / lux s m^2 x (400 um)^2 x QE 0.5), so flat_wall's
// values of 0.30 to 2.7 (at the default 1/100 s) fill the 20000 e well many
// times over and every pixel clips: one warning, with the share, the pitch
// and the way out. A 0.36 x 0.24 mm sensor (4 um pixels, 25500 e per value)
// at 1/500 s puts the brightest channel, 0.55, at 14000 e: nothing clips, and
// nothing is said.
TEST(SensorNoiseCli, ClippingMostPixelsWarnsOnce) {
  const TempDir dir;
  const auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {
        "render", kScene, "--film", "irradiance", "--exposure", "physical", "--res", "90x60", "--spp", "2",
        "--noise", "on", "-o", (dir / "a.exr").string(),
        // Spectral: its colour noise at 2 spp is what brings the brightest channel near the well.
        "--spectral", "on"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runLensrt(args);
  };
  const std::string warning = "of the pixels clip at the sensor's full well";
  const RunResult full = run({});
  ASSERT_EQ(full.status, 0) << full.err;
  const std::size_t at = full.err.find(warning);
  ASSERT_NE(at, std::string::npos) << full.err;
  EXPECT_EQ(full.err.find(warning, at + 1), std::string::npos) << "more than once:\n" << full.err;
  for (const char* part : {"100% of the pixels", "full well (20000 e)", "its 400 um pixels", "--sensor",
                           "--res", "a lower exposure (--iso, --shutter, --fstop)"})
    EXPECT_NE(full.err.find(part), std::string::npos) << part << "\n" << full.err;
  const RunResult normal = run({"--sensor", "0.36x0.24", "--shutter", "1/500"});
  ASSERT_EQ(normal.status, 0) << normal.err;
  EXPECT_EQ(normal.err.find(warning), std::string::npos) << normal.err;
  ImageMetadata meta;
  const Image img = readImage(dir / "a.exr", &meta);
  double peak = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (const char* c : {"noiseless.R", "noiseless.G", "noiseless.B"})
        peak = std::max(peak, double(img.at(x, y, img.channelIndex(c))));
  // The silence means something only if the render comes near the well.
  EXPECT_GT(peak * std::stod(meta["lensrt:sensor_electrons_per_value"]), 10000.0);
}

// The warning is about the image written. With --checkpoint each checkpoint
// is read out too, and in the Cornell box (400 um pixels again) its clipped
// share grows as the noise settles: 52%, 60%, 62% after 1, 2 and 4 spp, 63%
// at 8. The checkpoints say nothing, so one warning gives the final share;
// -q silences it as it does every warning.
TEST(SensorNoiseCli, ClippingWarnsOnceForTheImageWrittenNotForEachCheckpoint) {
  const TempDir dir;
  const std::string cornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";
  const auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"render",       cornell,    "--film",  "irradiance",
                                     "--exposure",   "physical", "--res",   "90x60",
                                     "--spp",        "8",        "--noise", "on",
                                     "--checkpoint", "1e-9",     "-o",      (dir / "a.exr").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return runLensrt(args);
  };
  const std::string warning = "of the pixels clip at the sensor's full well";
  const RunResult loud = run({});
  ASSERT_EQ(loud.status, 0) << loud.err;
  const std::size_t at = loud.err.find(warning);
  ASSERT_NE(at, std::string::npos) << loud.err;
  EXPECT_EQ(loud.err.find(warning, at + 1), std::string::npos) << "more than once:\n" << loud.err;
  // The share given is the written image's.
  const Image img = readImage(dir / "a.exr");
  const int g = img.channelIndex("G");
  float top = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      top = std::max({top, img.at(x, y, g - 1), img.at(x, y, g), img.at(x, y, g + 1)});
  int clipped = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      clipped += img.at(x, y, g - 1) == top || img.at(x, y, g) == top || img.at(x, y, g + 1) == top;
  const std::string share = fmt::format("{:.0f}% of the pixels", 100.0 * clipped / (img.width * img.height));
  EXPECT_NE(loud.err.find(share), std::string::npos) << share << "\n" << loud.err;

  const RunResult quiet = run({"-q"});
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
}

}  // namespace
}  // namespace lensrt
