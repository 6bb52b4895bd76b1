// --dispersion end to end: the EXR says which, tiles and a resumed render
// with dispersion give the bits of the whole render, and merge and resume
// refuse to join renders made with and without it.
#include <gtest/gtest.h>

#include <cstring>

#include "cli/cli_util.h"
#include "image/image_io.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kCornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";

std::vector<std::string> renderArgs(const std::string& out, std::vector<std::string> extra, int spp = 3) {
  std::vector<std::string> a{"render",  kCornell, "--res",    "24x17", "--spp",  std::to_string(spp),
                             "--seed",  "4",      "--camera", "lens",  "--lens", "dgauss-100mm",
                             "--fstop", "4",      "-q",       "-o",    out};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

void expectSameBits(const std::filesystem::path& a, const std::filesystem::path& b) {
  const Image x = readImage(a), y = readImage(b);
  ASSERT_EQ(x.pixels.size(), y.pixels.size());
  EXPECT_EQ(std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)), 0) << b;
}

TEST(DispersionCli, MetadataAndTilesAndMergeIdentity) {
  const TempDir dir;
  const std::string whole = (dir / "whole.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(whole, {})).status, 0);
  // Tiles with dispersion merge to the whole render's bits.
  const std::string t0 = (dir / "t0.exr").string(), t1 = (dir / "t1.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(t0, {"--tile", "0/2"})).status, 0);
  ASSERT_EQ(runLensrt(renderArgs(t1, {"--tile", "1/2"})).status, 0);
  const std::string merged = (dir / "merged.exr").string();
  RunResult r = runLensrt({"merge", "-q", "-o", merged, t0, t1});
  ASSERT_EQ(r.status, 0) << r.err;
  expectSameBits(whole, merged);

  // A part made without dispersion is another render (and other pixels).
  const std::string t1off = (dir / "t1off.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(t1off, {"--tile", "1/2", "--dispersion", "off"})).status, 0);
  ImageMetadata onMeta, offMeta;
  const Image on = readImage(t1, &onMeta), off = readImage(t1off, &offMeta);
  EXPECT_EQ(onMeta["lensrt:dispersion"], "on");  // the default for a lens with Abbe numbers
  EXPECT_EQ(offMeta["lensrt:dispersion"], "off");
  ASSERT_EQ(on.pixels.size(), off.pixels.size());
  EXPECT_NE(std::memcmp(on.pixels.data(), off.pixels.data(), on.pixels.size() * sizeof(float)), 0);
  r = runLensrt({"merge", "-q", "-o", (dir / "bad.exr").string(), t0, t1off});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("the camera differs"), std::string::npos) << r.err;
  EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
}

TEST(DispersionCli, ResumeGivesTheWholeRendersBitsAndRefusesTheOtherSetting) {
  const TempDir dir;
  const std::string whole = (dir / "whole.exr").string(), ck = (dir / "ck.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(whole, {}, 5)).status, 0);
  ASSERT_EQ(runLensrt(renderArgs(ck, {"--checkpoint", "1000"}, 2)).status, 0);
  RunResult r =
      runLensrt(renderArgs((dir / "other.exr").string(), {"--resume", ck, "--dispersion", "off"}, 5));
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("the camera differs"), std::string::npos) << r.err;
  r = runLensrt(renderArgs(ck, {"--resume", ck, "--checkpoint", "1000"}, 5));
  ASSERT_EQ(r.status, 0) << r.err;
  expectSameBits(whole, ck);
}

}  // namespace
}  // namespace lensrt
