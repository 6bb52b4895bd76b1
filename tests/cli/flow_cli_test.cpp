// --aov flow through the command line (docs/ground-truth.md, "Flow"; the
// closed forms are tests/python/test_flow.py's): on the spinning propeller
// (scenes/propeller.gltf) the still checker wall behind it moves by exactly
// 0 px while the blades move, forward and backward, over a frame and over
// the shutter; and the flow's bits do not depend on the thread count or the
// tile size, and merged --tile parts are the whole render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kPropeller = std::string(LENSRT_SOURCE_DIR) + "/scenes/propeller.gltf";

Image renderFlow(const TempDir& dir, const std::string& name, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"render",
                                   kPropeller,
                                   "--res",
                                   "24x24",
                                   "--spp",
                                   "2",
                                   "--aov",
                                   "flow",
                                   "--max-depth",
                                   "0",
                                   "-q",
                                   "-o",
                                   (dir / name).string()};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runLensrt(args);
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? readImage(dir / name) : Image();
}

// Pixels whose flow is exactly 0 in both directions, and the largest motion.
struct FlowSummary {
  int still = 0;
  double largest = 0;
};
FlowSummary summarise(const Image& image) {
  FlowSummary s;
  int c[4];
  int k = 0;
  for (const char* name : {"flow.forward.X", "flow.forward.Y", "flow.backward.X", "flow.backward.Y"}) {
    c[k] = image.channelIndex(name);
    EXPECT_GE(c[k++], 0) << name;
  }
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      double sum = 0;
      for (int i : c) sum += std::abs(image.at(x, y, i));
      s.still += sum == 0;
      s.largest = std::max(s.largest, double(std::hypot(image.at(x, y, c[0]), image.at(x, y, c[1]))));
    }
  return s;
}

TEST(FlowCli, TheStillWallStaysAndTheBladesMove) {
  const TempDir dir;
  // Over a frame (--frame 5: to frames 4 and 6) and over a 1/500 s shutter.
  for (const std::vector<std::string>& when :
       {std::vector<std::string>{"--frame", "5", "--shutter", "0"},
        std::vector<std::string>{"--time", "0.2", "--shutter", "0.002"}}) {
    const Image image = renderFlow(dir, "p.exr", when);
    const FlowSummary s = summarise(image);
    // The blades and hub cover a few of the 576 pixels; the wall all the others.
    EXPECT_GT(s.still, 400) << when[0];
    EXPECT_LT(s.still, 576) << when[0];
    EXPECT_GT(s.largest, 0.5) << when[0];
  }
}

TEST(FlowCli, MergedTilesAreTheWholeRender) {
  const TempDir dir;
  const Image whole = renderFlow(dir, "whole.exr", {"--frame", "5"});
  renderFlow(dir, "t0.exr", {"--frame", "5", "--tile", "0/2"});
  renderFlow(dir, "t1.exr", {"--frame", "5", "--tile", "1/2"});
  const RunResult m = runLensrt({"merge", "-q", "-o", (dir / "merged.exr").string(),
                                 (dir / "t0.exr").string(), (dir / "t1.exr").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  const Image merged = readImage(dir / "merged.exr");
  ASSERT_EQ(merged.pixels.size(), whole.pixels.size());
  EXPECT_EQ(merged.channels, whole.channels);
  EXPECT_EQ(std::memcmp(merged.pixels.data(), whole.pixels.data(), whole.pixels.size() * sizeof(float)), 0);
}

TEST(FlowCli, TheBitsDoNotDependOnThreadsOrTiles) {
  const TempDir dir;
  const Image one = renderFlow(dir, "one.exr", {"--frame", "5", "--threads", "1"});
  const Image two = renderFlow(dir, "two.exr", {"--frame", "5", "--threads", "2", "--tile-size", "5"});
  ASSERT_EQ(one.pixels.size(), two.pixels.size());
  EXPECT_EQ(std::memcmp(one.pixels.data(), two.pixels.data(), one.pixels.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace lensrt
