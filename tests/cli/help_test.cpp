// `lensrt --help` lists one line per command; each command's own --help keeps
// its long text (diff's statistics, the examples).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;

TEST(Help, TheTopLevelListsOneLinePerCommand) {
  const RunResult r = runLensrt({"--help"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> lines = cli::lines(r.out);
  std::size_t start = 0;
  while (start < lines.size() && lines[start] != "Subcommands:") ++start;
  ASSERT_LT(start, lines.size()) << r.out;
  std::vector<std::string> listed;
  for (std::size_t i = start + 1; i < lines.size() && !lines[i].empty(); ++i) {
    EXPECT_EQ(lines[i].rfind("  ", 0), 0u) << lines[i];
    EXPECT_NE(lines[i][2], ' ') << "a continuation line: " << lines[i];
    EXPECT_LE(lines[i].size(), 130u) << lines[i];
    listed.push_back(lines[i].substr(2, lines[i].find(' ', 2) - 2));
  }
  EXPECT_EQ(listed,
            (std::vector<std::string>{"render", "lens", "diff", "compare", "merge", "sensor", "options"}))
      << r.out;
}

TEST(Help, ACommandsHelpKeepsItsLongText) {
  const RunResult diff = runLensrt({"diff", "--help"});
  ASSERT_EQ(diff.status, 0) << diff.err;
  EXPECT_NE(diff.out.find("--noise-aware (both images need variance.R/G/B"), std::string::npos) << diff.out;
  EXPECT_NE(diff.out.find("Exit status: 0 identical"), std::string::npos) << diff.out;
  const RunResult render = runLensrt({"render", "--help"});
  EXPECT_NE(render.out.find("Example: lensrt render scenes/dof_row.gltf"), std::string::npos) << render.out;
  EXPECT_NE(render.out.find("(PNG, JPEG, BMP or TGA)"), std::string::npos) << render.out;
}

}  // namespace
}  // namespace lensrt
