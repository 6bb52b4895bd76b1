// `lensrt render --noise-threshold` end to end: the spp channel and the
// lensrt:spp summary, the bits across threads, tiles merged, checkpoints
// resumed and camera models, old checkpoints refused in one line, `lensrt
// compare` and `lensrt diff --noise-aware` on adaptive images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <nlohmann/json.hpp>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kCornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";
const std::string kDofRow = std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf";

std::vector<std::string> adaptiveArgs(const std::string& out, std::vector<std::string> extra, int spp = 64,
                                      const std::string& seed = "11", const std::string& threshold = "0.05") {
  std::vector<std::string> a{
      "render", kCornell, "--res",    "24x17",     "--spp", std::to_string(spp), "--seed",
      seed,     "--aov",  "variance", "--min-spp", "4",     "--noise-threshold", threshold,
      "-q",     "-o",     out};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

void expectSameBits(const std::filesystem::path& a, const std::filesystem::path& b) {
  const Image x = readImage(a), y = readImage(b);
  ASSERT_EQ(x.channels, y.channels);
  ASSERT_EQ(x.pixels.size(), y.pixels.size());
  EXPECT_EQ(std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)), 0)
      << a << " " << b;
}

std::vector<float> sppOf(const Image& image) {
  const int c = image.channelIndex("spp");
  std::vector<float> v;
  if (c < 0) return v;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) v.push_back(image.at(x, y, c));
  return v;
}

TEST(AdaptiveCli, SppChannelAndMetadataSayWhatEachPixelTook) {
  const TempDir dir;
  const std::string out = (dir / "a.exr").string();
  const RunResult r = runLensrt(adaptiveArgs(out, {}));
  ASSERT_EQ(r.status, 0) << r.err;
  ImageMetadata meta;
  const Image img = readImage(out, &meta);
  const std::vector<float> spp = sppOf(img);
  ASSERT_EQ(spp.size(), 24u * 17u);
  const auto [lo, hi] = std::minmax_element(spp.begin(), spp.end());
  EXPECT_GE(*lo, 4.0f);
  EXPECT_LE(*hi, 64.0f);
  EXPECT_LT(*lo, *hi);  // some pixels stop before others
  double mean = 0;
  for (const float v : spp) mean += v;
  mean /= double(spp.size());
  char expected[96];
  std::snprintf(expected, sizeof expected, "adaptive min=%.0f mean=%.2f max=%.0f", double(*lo), mean,
                double(*hi));
  EXPECT_EQ(meta["lensrt:spp"], expected);
  EXPECT_EQ(meta["lensrt:samples_done"], "64");
  EXPECT_EQ(meta["lensrt:camera_samples"], std::to_string(std::uint64_t(mean * double(spp.size()) + 0.5)));
  EXPECT_NE(meta["lensrt:settings"].find("noise_threshold=0.05 min_spp=4"), std::string::npos);

  // Without --noise-threshold: no spp channel, a count in lensrt:spp.
  const std::string fixed = (dir / "f.exr").string();
  ASSERT_EQ(runLensrt({"render", kCornell, "--res", "24x17", "--spp", "4", "-q", "-o", fixed}).status, 0);
  ImageMetadata fixedMeta;
  EXPECT_EQ(readImage(fixed, &fixedMeta).channelIndex("spp"), -1);
  EXPECT_EQ(fixedMeta["lensrt:spp"], "4");
  EXPECT_EQ(fixedMeta.count("lensrt:samples_done"), 0u);
}

TEST(AdaptiveCli, ThreadsTilesMergeAndResumeKeepTheBits) {
  const TempDir dir;
  const std::string whole = (dir / "whole.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(whole, {"--threads", "2"})).status, 0);
  const std::string one = (dir / "one.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(one, {"--threads", "1", "--tile-size", "5"})).status, 0);
  expectSameBits(whole, one);

  // Tiles merged.
  std::vector<std::string> merge{"merge", "-q", "-o", (dir / "merged.exr").string()};
  for (int i = 0; i < 3; ++i) {
    const std::string part = (dir / (std::to_string(i) + "of3.exr")).string();
    const RunResult r = runLensrt(adaptiveArgs(part, {"--tile", std::to_string(i) + "/3"}));
    ASSERT_EQ(r.status, 0) << r.err;
    merge.push_back(part);
  }
  const RunResult m = runLensrt(merge);
  ASSERT_EQ(m.status, 0) << m.err;
  expectSameBits(whole, merge[3]);
  ImageMetadata wholeMeta, mergedMeta;
  readImage(whole, &wholeMeta);
  readImage(merge[3], &mergedMeta);
  EXPECT_EQ(mergedMeta["lensrt:spp"], wholeMeta["lensrt:spp"]);
  EXPECT_EQ(mergedMeta["lensrt:camera_samples"], wholeMeta["lensrt:camera_samples"]);
  // A part of a render to another maximum is not a part of this one.
  const std::string other = (dir / "other.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(other, {"--tile", "1/3"}, 32)).status, 0);
  const RunResult bad = runLensrt({"merge", "-q", "-o", (dir / "bad.exr").string(), merge[4], other});
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.err.find("has 32 spp"), std::string::npos) << bad.err;

  // A checkpoint to 16 spp resumed to 64: the uninterrupted render's bits.
  const std::string ck = (dir / "ck.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(ck, {"--checkpoint", "1000"}, 16)).status, 0);
  const RunResult resumed = runLensrt(adaptiveArgs(ck, {"--resume", ck, "--checkpoint", "1000"}));
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  expectSameBits(whole, ck);
}

TEST(AdaptiveCli, ACheckpointOfAnotherSamplingIsRefusedInOneLine) {
  const TempDir dir;
  // A checkpoint of a fixed-spp render (as older versions wrote) cannot be
  // continued adaptively, nor an adaptive one with another threshold.
  const std::string fixed = (dir / "fixed.exr").string(), out = (dir / "out.exr").string();
  ASSERT_EQ(runLensrt({"render", kCornell, "--res", "24x17", "--spp", "2", "--seed", "11", "--aov",
                       "variance", "--checkpoint", "1000", "-q", "-o", fixed})
                .status,
            0);
  const std::string adaptive = (dir / "adaptive.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(adaptive, {"--checkpoint", "1000"}, 8)).status, 0);
  for (const auto& [from, threshold] : {std::pair{fixed, "0.05"}, std::pair{adaptive, "0.1"}}) {
    const RunResult r = runLensrt(adaptiveArgs(out, {"--resume", from}, 64, "11", threshold));
    EXPECT_EQ(r.status, 1) << from << r.err;
    EXPECT_NE(r.err.find("the settings differ"), std::string::npos) << r.err;
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  // Without adaptive sampling, the old checkpoint still resumes.
  const RunResult plain = runLensrt({"render", kCornell, "--res", "24x17", "--spp", "4", "--seed", "11",
                                     "--aov", "variance", "--resume", fixed, "-q", "-o", out});
  EXPECT_EQ(plain.status, 0) << plain.err;
}

TEST(AdaptiveCli, EveryCameraModelStopsPixelsWithTheSameBitsOnAnyThreads) {
  const TempDir dir;
  for (const std::vector<std::string>& camera :
       {std::vector<std::string>{"--camera", "pinhole"},
        {"--camera", "thin", "--fstop", "2", "--focus", "2"},
        {"--camera", "thick", "--lens", "dgauss-50mm", "--focus", "2"},
        {"--camera", "lens", "--lens", "dgauss-50mm", "--fstop", "2", "--focus", "2"}}) {
    SCOPED_TRACE(camera[1]);
    std::vector<std::string> args{
        "render", kDofRow,  "--res", "32x18", "--spp", "32", "--min-spp", "4", "--noise-threshold",
        "0.1",    "--seed", "3",     "-q"};
    args.insert(args.end(), camera.begin(), camera.end());
    std::vector<std::string> a = args, b = args;
    a.insert(a.end(), {"--threads", "1", "-o", (dir / "a.exr").string()});
    b.insert(b.end(), {"--threads", "2", "--tile-size", "3", "-o", (dir / "b.exr").string()});
    const RunResult ra = runLensrt(a), rb = runLensrt(b);
    ASSERT_EQ(ra.status, 0) << ra.err;
    ASSERT_EQ(rb.status, 0) << rb.err;
    expectSameBits(dir / "a.exr", dir / "b.exr");
    const std::vector<float> spp = sppOf(readImage(dir / "a.exr"));
    ASSERT_FALSE(spp.empty());
    EXPECT_EQ(*std::min_element(spp.begin(), spp.end()), 4.0f);
    EXPECT_GT(*std::max_element(spp.begin(), spp.end()), 4.0f);
  }
}

TEST(AdaptiveCli, CompareRendersEveryModelAdaptively) {
  const TempDir tmp;
  const std::filesystem::path dir = tmp / "cmp";
  const RunResult r =
      runLensrt({"compare", kDofRow, "--lens", "dgauss-50mm", "--focus", "2", "--spp", "16", "--min-spp", "4",
                 "--noise-threshold", "0.1", "--res", "32x18", "--seed", "1", "-q", "-o", dir.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(cli::readFile(dir / "report.json"));
  EXPECT_EQ(report.at("settings").at("noise_threshold").get<double>(), 0.1);
  EXPECT_EQ(report.at("settings").at("min_spp").get<int>(), 4);
  for (const char* model : {"pinhole", "thin", "thick", "lens"}) {
    SCOPED_TRACE(model);
    ImageMetadata meta;
    const Image img = readImage(dir / (std::string(model) + ".exr"), &meta);
    EXPECT_FALSE(sppOf(img).empty());
    EXPECT_EQ(meta["lensrt:spp"].rfind("adaptive min=4 ", 0), 0u) << meta["lensrt:spp"];
    const double mean = report.at("models").at(model).at("mean_spp").get<double>();
    EXPECT_GE(mean, 4.0);
    EXPECT_LT(mean, 16.0);
  }
}

TEST(AdaptiveCli, NoiseAwareDiffUsesEachPixelsSamples) {
  const TempDir dir;
  const std::string s1 = (dir / "s1.exr").string(), s2 = (dir / "s2.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(s1, {}, 64, "21")).status, 0);
  ASSERT_EQ(runLensrt(adaptiveArgs(s2, {}, 64, "22")).status, 0);
  const RunResult same = runLensrt({"diff", s1, s2, "--noise-aware", "--json"});
  EXPECT_EQ(same.status, 0) << same.out << same.err;
  const nlohmann::json j = nlohmann::json::parse(same.out);
  // The fewest samples a pixel took in either image: 4, so 3 degrees of freedom
  // (lensrt:spp holds no single count).
  EXPECT_EQ(j.at("noiseAware").at("degreesOfFreedom").get<double>(), 3.0);
  // A brighter scene (another light) fails.
  const std::string bright = (dir / "bright.exr").string();
  ASSERT_EQ(runLensrt(adaptiveArgs(bright, {"--env", "constant:0.3"}, 64, "23")).status, 0);
  EXPECT_NE(runLensrt({"diff", s1, bright, "--noise-aware"}).status, 0);
}

}  // namespace
}  // namespace lensrt
