// Every command that writes a file creates the folder it goes to, with its
// missing parents, and says so once; a folder that cannot be made (a file on
// the way) is one error line.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

const std::string kFurnace = std::string(LENSRT_SOURCE_DIR) + "/scenes/furnace.gltf";

int createdNotes(const std::string& err) {
  int n = 0;
  for (const std::string& line : cli::lines(err)) n += line.rfind("lensrt: created folder ", 0) == 0;
  return n;
}

TEST(OutputFolder, EveryCommandCreatesTheFolderOfItsOutput) {
  const TempDir dir;
  const auto at = [&](const std::string& p) { return (dir / p).string(); };
  struct Case {
    std::vector<std::string> args;
    std::vector<std::string> written;
    int folders;  // made by this command: one note each
  };
  const std::vector<Case> cases{
      {{"render", kFurnace, "--res", "8x8", "--spp", "1", "--checkpoint", "100", "-o", at("r/a/x.exr")},
       {"r/a/x.exr", "r/a/x.exr.sums"},
       1},
      {{"render", kFurnace, "--res", "8x8", "--spp", "1", "--tile", "0/2", "--aov", "variance", "-o",
        at("parts/0.exr")},
       {"parts/0.exr"},
       1},
      {{"render", kFurnace, "--res", "8x8", "--spp", "1", "--tile", "1/2", "--aov", "variance", "-o",
        at("parts/1.exr")},
       {"parts/1.exr"},
       0},
      {{"merge", at("parts/0.exr"), at("parts/1.exr"), "-o", at("m/n/whole.exr")}, {"m/n/whole.exr"}, 1},
      {{"diff", at("parts/0.exr"), at("parts/0.exr"), "--heatmap", at("d/e/h.png")}, {"d/e/h.png"}, 1},
      {{"compare", kFurnace, "--lens", "dgauss-50mm", "--res", "8x8", "--spp", "1", "-o", at("c/d/cmp")},
       {"c/d/cmp/report.html"},
       1},
      {{"lens", "diagram", "dgauss-50mm", "-o", at("l/m/lens.svg")}, {"l/m/lens.svg"}, 1},
      {{"lens", "plot", "dgauss-50mm", "--what", "distortion", "-o", at("p/q/plot.svg"), "--csv",
        at("s/t/plot.csv")},
       {"p/q/plot.svg", "s/t/plot.csv"},
       2},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args[0] + " " + c.args.back());
    const RunResult r = runLensrt(c.args);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const std::string& w : c.written) EXPECT_TRUE(std::filesystem::exists(dir / w)) << w;
    // One note per folder made (the second part's folder already exists).
    const int expected =
        c.args.back() == at("parts/1.exr") ? 0 : int(c.written.size() == 2 && c.args[0] == "lens" ? 2 : 1);
    EXPECT_EQ(createdNotes(r.err), expected) << r.err;
  }
  // Quiet commands make the folder without a word.
  const RunResult quiet =
      runLensrt({"render", kFurnace, "--res", "8x8", "--spp", "1", "-q", "-o", at("quiet/a.exr")});
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "quiet/a.exr"));
  EXPECT_EQ(quiet.err, "");
}

TEST(OutputFolder, LensDiagramAndPlotSayWhatTheyWrote) {
  const TempDir dir;
  const RunResult d = runLensrt({"lens", "diagram", "dgauss-50mm", "-o", (dir / "lens.svg").string()});
  ASSERT_EQ(d.status, 0) << d.err;
  EXPECT_EQ(d.err, "lensrt: wrote " + (dir / "lens.svg").string() + "\n");
  const RunResult p = runLensrt({"lens", "plot", "dgauss-50mm", "--what", "spot", "--csv", "-"});
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_EQ(p.err, "");  // the CSV went to standard output
}

TEST(OutputFolder, AChromaticPlotOfALensWithoutDispersionDataSaysSo) {
  const TempDir dir;
  const RunResult r =
      runLensrt({"lens", "plot", "fisheye-10mm", "--what", "chromatic", "-o", (dir / "c.svg").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("lensrt: warning: fisheye-10mm: no dispersion data"), std::string::npos) << r.err;
  const RunResult withData =
      runLensrt({"lens", "plot", "dgauss-100mm", "--what", "chromatic", "-o", (dir / "d.svg").string()});
  ASSERT_EQ(withData.status, 0) << withData.err;
  EXPECT_EQ(withData.err.find("no dispersion data"), std::string::npos) << withData.err;
}

}  // namespace
}  // namespace lensrt
