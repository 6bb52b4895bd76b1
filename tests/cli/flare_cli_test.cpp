// --flare on (stray light in the full lens), end to end on a uniform sky:
// - with --flare-bounces 0 the camera samples the pupil another way (a
//   mixture of the exit pupil bounds and the whole rear element) but traces
//   the same light: its image matches --flare off's within 0.5% (measured
//   0.1%; counting the rear-element half of the mixture at full density
//   instead of half gives 0.816);
// - reflections only move light the lens let in, so two bounces add the
//   ghosts' and the glare's share, which multi-coating cuts by more than 50x
//   (R 0.5% a surface against bare glass's 4-6%; measured +5.6% and +0.015%).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

double meanRed(const TempDir& dir, const std::vector<std::string>& extra, const char* spp = "128") {
  if (!std::filesystem::exists(dir / "sky.gltf")) cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  std::vector<std::string> args{"render",
                                (dir / "sky.gltf").string(),
                                "--env",
                                "constant:1",
                                "--camera",
                                "lens",
                                "--lens",
                                "dgauss-50mm",
                                "--fstop",
                                "2.8",
                                "--spectral",
                                "off",
                                "--res",
                                "32x24",
                                "--spp",
                                spp,
                                "-q",
                                "-o",
                                (dir / "a.exr").string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  const Image img = readImage(dir / "a.exr");
  double sum = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += img.at(x, y, img.channelIndex("R"));
  return sum / (double(img.width) * img.height);
}

// Blades with flare: the flare trace cuts the stop to the same hexagon as
// the ordinary trace, so without reflections the two images agree (measured
// 1.0009); the round stop the hexagon is cut from lets in up to 2 pi / (3
// sqrt 3) = 1.21 times the light (measured with the polygon left out of
// the flare trace: 1.149). A barrel of K = 0.5 adds 0.41% to the frame.
TEST(FlareCli, BladesShapeTheStopOfTheFlareTraceToo) {
  const TempDir dir;
  const double off = meanRed(dir, {"--coatings", "none", "--blades", "6"});
  const double zero =
      meanRed(dir, {"--coatings", "none", "--blades", "6", "--flare", "on", "--flare-bounces", "0"});
  std::printf("6 blades, flare on without reflections over flare off: %.4f\n", zero / off);
  EXPECT_NEAR(zero / off, 1.0, 0.005);
  // The same with a grey-scale mask (a triangle): its transmittance at every crossing of the stop.
  const std::string mask =
      std::string(LENSRT_SOURCE_DIR) + "/tests/fuzz/corpus/fuzz_aperture_mask/triangle-32-grey8.png";
  // More samples: the mask's weights are noisier (at 128 spp 0.993; at 1024
  // spp 0.9992). The flare trace without the mask gives 2.30 (0.5154 for 0.2237).
  const double maskOff = meanRed(dir, {"--coatings", "none", "--aperture-mask", mask}, "1024");
  const double maskZero = meanRed(
      dir, {"--coatings", "none", "--aperture-mask", mask, "--flare", "on", "--flare-bounces", "0"}, "1024");
  std::printf("mask, flare on without reflections over flare off: %.4f\n", maskZero / maskOff);
  EXPECT_NEAR(maskZero / maskOff, 1.0, 0.005);
  // And the barrel adds a little light to the frame, never takes any.
  const double two = meanRed(dir, {"--coatings", "none", "--flare", "on"});
  const double barrel = meanRed(dir, {"--coatings", "none", "--flare", "on", "--barrel-reflectance", "0.5"});
  std::printf("barrel 0.5 over black: %.5f\n", barrel / two);
  EXPECT_GT(barrel, two);
}

TEST(FlareCli, NoReflectionsIsTheImageWithoutFlare) {
  const TempDir dir;
  const double off = meanRed(dir, {"--coatings", "none"});
  const double zero = meanRed(dir, {"--coatings", "none", "--flare", "on", "--flare-bounces", "0"});
  EXPECT_NEAR(zero / off, 1.0, 0.005);
}

TEST(FlareCli, GhostsAddLightThatMultiCoatingCuts) {
  const TempDir dir;
  const auto added = [&](const std::string& coating) {
    const double zero = meanRed(dir, {"--coatings", coating, "--flare", "on", "--flare-bounces", "0"});
    const double two = meanRed(dir, {"--coatings", coating, "--flare", "on", "--flare-bounces", "2"});
    return (two - zero) / zero;
  };
  const double bare = added("none"), multi = added("multi");
  EXPECT_GT(bare, 0.02);  // the double Gauss's 45 ghosts and its glare under a uniform sky: about 6%
  EXPECT_GE(multi, 0.0);
  EXPECT_LT(multi * 50, bare) << "bare glass adds " << bare << ", multi-coated " << multi;
}

// The flare trace's choices come from each sample's own numbers: the same
// bits on 1 or 2 threads and from two tiles merged.
TEST(FlareCli, FlareIsTheSameBitsOnAnyThreadsAndTiles) {
  const TempDir dir;
  const std::string scene = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";
  const auto render = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> a{"render",
                               scene,
                               "--camera",
                               "lens",
                               "--lens",
                               "dgauss-50mm",
                               "--fstop",
                               "2.8",
                               "--flare",
                               "on",
                               "--res",
                               "40x24",
                               "--spp",
                               "4",
                               "-q",
                               "-o",
                               (dir / out).string()};
    a.insert(a.end(), extra.begin(), extra.end());
    const RunResult r = runLensrt(a);
    ASSERT_EQ(r.status, 0) << r.err;
  };
  render("t1.exr", {"--threads", "1"});
  render("t2.exr", {"--threads", "2"});
  render("p0.exr", {"--tile", "0/2"});
  render("p1.exr", {"--tile", "1/2"});
  const RunResult m = runLensrt(
      {"merge", (dir / "p0.exr").string(), (dir / "p1.exr").string(), "-o", (dir / "m.exr").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  const Image one = readImage(dir / "t1.exr");
  EXPECT_EQ(one.pixels, readImage(dir / "t2.exr").pixels);
  EXPECT_EQ(one.pixels, readImage(dir / "m.exr").pixels);
}

// A lamp in frame (scenes/point_light_plane: a 1 W/sr point light 1 m below
// the camera, above a plane): camera paths never see a punctual light, so
// without the light pass the lamp is invisible; with --flare on its image
// through the lens (and its ghosts) is added, from the light pass. The
// brightest pixel is then the lamp's, at the centre, and the pass keeps the
// bits across threads, tiles merged and a resumed checkpoint.
TEST(FlareCli, ALampInFrameShowsAsTheLenssImageOfAPoint) {
  const TempDir dir;
  const std::string scene = std::string(LENSRT_SOURCE_DIR) + "/scenes/point_light_plane.gltf";
  const auto render = [&](const std::string& name, const std::vector<std::string>& extra,
                          const std::string& spp = "4") {
    std::vector<std::string> a{"render", scene, "-q", "-o", (dir / name).string(), "--spp", spp};
    for (const char* arg : {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "4", "--focus", "1",
                            "--spectral", "off", "--coatings", "none", "--res", "48x48"})
      a.emplace_back(arg);
    a.insert(a.end(), extra.begin(), extra.end());
    const RunResult r = runLensrt(a);
    ASSERT_EQ(r.status, 0) << r.err;
  };
  render("off.exr", {});
  render("on.exr", {"--flare", "on", "--threads", "1"});
  const Image off = readImage(dir / "off.exr"), on = readImage(dir / "on.exr");
  const int red = on.channelIndex("R");
  double brightest = 0, offBrightest = 0;
  int bx = -1, by = -1;
  for (int y = 0; y < on.height; ++y)
    for (int x = 0; x < on.width; ++x) {
      if (on.at(x, y, red) > brightest) brightest = on.at(x, y, red), bx = x, by = y;
      offBrightest = std::max(offBrightest, double(off.at(x, y, red)));
    }
  std::printf("lamp: brightest %.4g at (%d, %d); without flare %.4g\n", brightest, bx, by, offBrightest);
  EXPECT_GT(brightest, 100 * offBrightest);
  EXPECT_TRUE((bx == 23 || bx == 24) && (by == 23 || by == 24)) << bx << "," << by;
  render("t2.exr", {"--flare", "on", "--threads", "2"});
  render("p0.exr", {"--flare", "on", "--tile", "0/2"});
  render("p1.exr", {"--flare", "on", "--tile", "1/2"});
  const RunResult m = runLensrt(
      {"merge", (dir / "p0.exr").string(), (dir / "p1.exr").string(), "-o", (dir / "m.exr").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(on.pixels, readImage(dir / "t2.exr").pixels);
  EXPECT_EQ(on.pixels, readImage(dir / "m.exr").pixels);
  // A checkpoint at 2 spp resumed to 4: the uninterrupted render's bits.
  render("ck.exr", {"--flare", "on", "--checkpoint", "1000"}, "2");
  render("ck.exr", {"--flare", "on", "--resume", (dir / "ck.exr").string(), "--checkpoint", "1000"});
  EXPECT_EQ(on.pixels, readImage(dir / "ck.exr").pixels);
}

TEST(FlareCli, FlareNeedsTheFullLensAndAnEvenNumberOfBounces) {
  const TempDir dir;
  cli::writeFile(dir / "sky.gltf", cli::kSkyOnlyGltf);
  const std::string out = (dir / "x.exr").string();
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--camera", "thin", "--flare", "on"},
            "--flare: stray light comes from the full lens's surfaces"},
           {{"--camera", "lens", "--lens", "dgauss-50mm", "--flare", "on", "--flare-bounces", "3"},
            "--flare-bounces"},
           {{"--camera", "lens", "--lens", "dgauss-50mm", "--flare", "on", "--barrel-reflectance", "1"},
            "--barrel-reflectance: expected a reflectance in [0, 1), got 1"},
           {{"--camera", "lens", "--lens", "dgauss-50mm", "--flare", "on", "--barrel-reflectance", "-0.1"},
            "--barrel-reflectance: expected a reflectance in [0, 1), got -0.1"},
           {{"--camera", "lens", "--lens", "dgauss-50mm", "--barrel-reflectance", "0.1"},
            "--barrel-reflectance: the barrel's stray light needs --flare on"}}) {
    std::vector<std::string> a{"render", (dir / "sky.gltf").string(), "-o", out};
    a.insert(a.end(), args.begin(), args.end());
    const RunResult r = runLensrt(a);
    EXPECT_EQ(r.status, 2) << says;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
}

}  // namespace
}  // namespace lensrt
