// Tiles, crops and merge; checkpoints, resume and interrupts, end to end:
// every way of cutting a render gives the bits of the uninterrupted render.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <thread>

#include "cli/cli_util.h"
#include "image/image_io.h"

extern char** environ;

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kCornell = std::string(LENSRT_SOURCE_DIR) + "/scenes/cornell.gltf";

std::vector<std::string> renderArgs(const std::string& out, std::vector<std::string> extra, int spp = 3) {
  std::vector<std::string> a{"render", kCornell,
                             "--res",  "24x17",
                             "--spp",  std::to_string(spp),
                             "--aov",  "depth,normal,albedo,variance",
                             "-q",     "-o",
                             out};
  if (std::find(extra.begin(), extra.end(), "--seed") == extra.end()) a.insert(a.end(), {"--seed", "11"});
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

void expectSameBits(const std::filesystem::path& a, const std::filesystem::path& b) {
  const Image x = readImage(a), y = readImage(b);
  ASSERT_EQ(x.channels, y.channels);
  ASSERT_EQ(x.width, y.width);
  ASSERT_EQ(x.height, y.height);
  ASSERT_TRUE(y.isWholeFrame());
  EXPECT_EQ(std::memcmp(x.pixels.data(), y.pixels.data(), x.pixels.size() * sizeof(float)), 0) << b;
}

TEST(Scaleout, MergedTilesAreTheWholeRender) {
  const TempDir dir;
  const std::string whole = (dir / "whole.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(whole, {})).status, 0);
  for (const int n : {1, 3, 7}) {
    std::vector<std::string> merge{"merge", "-q", "-o",
                                   (dir / ("merged" + std::to_string(n) + ".exr")).string()};
    for (int i = n - 1; i >= 0; --i) {  // any order
      const std::string part = (dir / (std::to_string(i) + "of" + std::to_string(n) + ".exr")).string();
      const RunResult r =
          runLensrt(renderArgs(part, {"--tile", std::to_string(i) + "/" + std::to_string(n)}));
      ASSERT_EQ(r.status, 0) << r.err;
      merge.push_back(part);
    }
    const RunResult m = runLensrt(merge);
    ASSERT_EQ(m.status, 0) << m.err;
    expectSameBits(whole, merge[3]);
    ImageMetadata meta;
    readImage(merge[3], &meta);
    EXPECT_EQ(meta["lensrt:spp"], "3");
    EXPECT_EQ(meta["lensrt:camera_samples"], std::to_string(24 * 17 * 3));
    EXPECT_EQ(meta.count("lensrt:region"), 0u);
  }
}

TEST(Scaleout, CropsMergeAndTheirDataWindowPlacesThem) {
  const TempDir dir;
  const std::string whole = (dir / "whole.exr").string(), a = (dir / "a.exr").string(),
                    b = (dir / "b.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(whole, {})).status, 0);
  ASSERT_EQ(runLensrt(renderArgs(a, {"--crop", "0,10,0,17"})).status, 0);
  ASSERT_EQ(runLensrt(renderArgs(b, {"--crop", "10,24,0,17"})).status, 0);
  const Image crop = readImage(b);
  EXPECT_EQ(crop.originX, 10);
  EXPECT_EQ(crop.width, 14);
  EXPECT_EQ(crop.fullWidth(), 24);
  const RunResult m = runLensrt({"merge", "-q", a, b, "-o", (dir / "m.exr").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  expectSameBits(whole, dir / "m.exr");
}

TEST(Scaleout, MergeRefusesOverlapGapAndOtherRenders) {
  const TempDir dir;
  const auto part = [&](const std::string& name, std::vector<std::string> extra, int spp = 3) {
    const std::string file = (dir / name).string();
    EXPECT_EQ(runLensrt(renderArgs(file, extra, spp)).status, 0);
    return file;
  };
  const std::string t0 = part("t0.exr", {"--tile", "0/2"}), t1 = part("t1.exr", {"--tile", "1/2"});
  const std::string seed = part("seed.exr", {"--tile", "1/2", "--seed", "12"});
  const std::string spp = part("spp.exr", {"--tile", "1/2"}, 2);
  const std::string crop = part("crop.exr", {"--crop", "0,24,8,10"});
  const std::string out = (dir / "out.exr").string();
  const auto merge = [&](std::vector<std::string> parts) {
    std::vector<std::string> args{"merge", "-o", out};
    args.insert(args.end(), parts.begin(), parts.end());
    return runLensrt(args);
  };
  RunResult r = merge({t0, crop, t1});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("overlap"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("crop.exr"), std::string::npos) << r.err;
  r = merge({t0});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("gap"), std::string::npos) << r.err;
  r = merge({t0, seed});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("seed.exr: is not a part of the render"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the seed differs ('12' against '11')"), std::string::npos) << r.err;
  r = merge({t0, spp});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("has 2 spp"), std::string::npos) << r.err;
  EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(Scaleout, ResumeContinuesToTheBitsOfTheUninterruptedRender) {
  const TempDir dir;
  const std::string whole = (dir / "whole.exr").string(), ck = (dir / "ck.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(whole, {}, 7)).status, 0);
  // A finished render with --checkpoint keeps its sums: resumable to more spp.
  ASSERT_EQ(runLensrt(renderArgs(ck, {"--checkpoint", "1000"}, 2)).status, 0);
  ASSERT_TRUE(std::filesystem::exists(ck + ".sums"));
  const RunResult r = runLensrt(renderArgs(ck, {"--resume", ck, "--checkpoint", "1000"}, 7));
  ASSERT_EQ(r.status, 0) << r.err;
  expectSameBits(whole, ck);
  ImageMetadata meta;
  readImage(ck, &meta);
  EXPECT_EQ(meta["lensrt:spp"], "7");
}

// --diffraction on draws each bend from a stream of its own and gives each
// sample its own wavelength: tiles and resume still give the whole render's bits.
TEST(Scaleout, DiffractionTilesAndResumeGiveTheBitsOfTheWholeRender) {
  const TempDir dir;
  const std::vector<std::string> lens{"--camera", "lens",          "--lens", "dgauss-50mm", "--fstop",
                                      "8",        "--diffraction", "on",     "--blades",    "7"};
  const auto with = [&](std::vector<std::string> extra) {
    extra.insert(extra.begin(), lens.begin(), lens.end());
    return extra;
  };
  const std::string whole = (dir / "whole.exr").string(), ck = (dir / "ck.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(whole, with({}), 5)).status, 0);
  std::vector<std::string> merge{"merge", "-q", "-o", (dir / "merged.exr").string()};
  for (const std::string tile : {"0/2", "1/2"}) {
    merge.push_back((dir / ("tile" + tile.substr(0, 1) + ".exr")).string());
    const RunResult r = runLensrt(renderArgs(merge.back(), with({"--tile", tile}), 5));
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const RunResult m = runLensrt(merge);
  ASSERT_EQ(m.status, 0) << m.err;
  expectSameBits(whole, merge[3]);
  ASSERT_EQ(runLensrt(renderArgs(ck, with({"--checkpoint", "1000"}), 2)).status, 0);
  const RunResult r = runLensrt(renderArgs(ck, with({"--resume", ck}), 5));
  ASSERT_EQ(r.status, 0) << r.err;
  expectSameBits(whole, ck);
}

TEST(Scaleout, ResumeRefusesAnotherRenderSayingWhatDiffers) {
  const TempDir dir;
  const std::string ck = (dir / "ck.exr").string(), out = (dir / "out.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(ck, {"--checkpoint", "1000"}, 2)).status, 0);
  const auto refused = [&](std::vector<std::string> extra, const std::string& what, int spp = 4) {
    extra.insert(extra.end(), {"--resume", ck});
    const RunResult r = runLensrt(renderArgs(out, extra, spp));
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_EQ(cli::lines(r.err).size(), 1u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  };
  refused({"--seed", "12"}, "the seed differs");
  refused({"--max-depth", "3"}, "the settings differ");
  refused({"--focal-length", "20"}, "the camera differs");
  refused({"--tile", "0/2"}, "covers pixels");
  refused({}, "more than --spp 1", 1);
  const std::string plain = (dir / "plain.exr").string();
  ASSERT_EQ(runLensrt(renderArgs(plain, {}, 2)).status, 0);
  const RunResult r = runLensrt(renderArgs(out, {"--resume", plain}, 4));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no running sums"), std::string::npos) << r.err;
  // Sums from another checkpoint.
  std::filesystem::copy_file(ck + ".sums", plain + ".sums");
  cli::writeFile(ck + ".sums", "LRTSUMS1 damaged");
  const RunResult d = runLensrt(renderArgs(out, {"--resume", ck}, 4));
  EXPECT_EQ(d.status, 1);
  EXPECT_NE(d.err.find("does not belong"), std::string::npos) << d.err;
}

// Starts lensrt, waits for its first checkpoint, interrupts it.
int interruptedRender(const std::vector<std::string>& args, const std::filesystem::path& firstFile,
                      int signals) {
  std::vector<std::string> argvStrings{LENSRT_BINARY};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, LENSRT_BINARY, nullptr, nullptr, argv.data(), environ) != 0) return -1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!std::filesystem::exists(firstFile) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  for (int i = 0; i < signals; ++i) {
    // Apart, so that the second is a second delivery rather than merged into
    // the first while it is pending.
    if (i > 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    kill(pid, SIGINT);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

TEST(Scaleout, AnInterruptedRenderWritesTheSamplesDoneAndResumes) {
  const TempDir dir;
  const std::string out = (dir / "int.exr").string();
  // Far more samples than the test waits for; the first checkpoint says it runs.
  const int status = interruptedRender({"render", kCornell, "--res", "8x6", "--spp", "1000000", "--seed", "2",
                                        "-q", "--checkpoint", "0.001", "-o", out},
                                       out + ".sums", 1);
  EXPECT_EQ(status, 130);
  ImageMetadata meta;
  readImage(out, &meta);
  const int spp = std::stoi(meta["lensrt:spp"]);
  EXPECT_GE(spp, 1);
  EXPECT_LT(spp, 1000000);
  EXPECT_EQ(meta["lensrt:spp_requested"], "1000000");
  // The samples it says it has are those of a render with that spp.
  const std::string whole = (dir / "whole.exr").string();
  ASSERT_EQ(runLensrt({"render", kCornell, "--res", "8x6", "--spp", std::to_string(spp), "--seed", "2", "-q",
                       "-o", whole})
                .status,
            0);
  expectSameBits(whole, out);
}

TEST(Scaleout, ASecondSignalExitsAtOnce) {
  const TempDir dir;
  const std::string out = (dir / "int.exr").string();
  // Signalled once the first checkpoint's image exists, not its sums (written
  // first): a second signal exits at once, and between the two writes it left
  // no image (CI, under the sanitizers).
  const int status = interruptedRender(
      {"render", kCornell, "--res", "8x6", "--spp", "1000000", "-q", "--checkpoint", "0.001", "-o", out}, out,
      2);
  EXPECT_EQ(status, 130);
  EXPECT_NO_THROW(readImage(out));  // whatever checkpoint was last written, whole
}

}  // namespace
}  // namespace lensrt
