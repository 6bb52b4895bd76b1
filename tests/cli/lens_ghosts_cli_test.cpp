// `lensrt lens ghosts`: the listing's text and JSON agree with the library
// (optics/ghosts, checked against closed forms in tests/optics), surfaces
// are numbered from 1, and bad arguments get one line and status 2.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;

TEST(LensGhostsCli, ListsEveryGhostStrongestFirstAsTextAndJson) {
  const RunResult j = runLensrt({"lens", "ghosts", "dgauss-50mm", "--coatings", "single", "--json"});
  ASSERT_EQ(j.status, 0) << j.err;
  const nlohmann::json doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["lens"], "dgauss-50mm");
  EXPECT_EQ(doc["coatings"], "single");
  const nlohmann::json& ghosts = doc["ghosts"];
  ASSERT_EQ(ghosts.size(), 45u);  // 10 surfaces where the index changes (the stop is the 11th)
  for (std::size_t i = 0; i < ghosts.size(); ++i) {
    const int first = ghosts[i]["surfaces"][0], second = ghosts[i]["surfaces"][1];
    EXPECT_GT(first, second);
    EXPECT_GE(second, 1);
    EXPECT_NEAR(ghosts[i]["relative_flux"].get<double>(),
                ghosts[i]["strength"].get<double>() * ghosts[i]["passing"].get<double>(), 1e-15);
    if (i > 0) {
      EXPECT_LE(ghosts[i]["strength"].get<double>(), ghosts[i - 1]["strength"].get<double>());
    }
  }
  const RunResult t = runLensrt({"lens", "ghosts", "dgauss-50mm", "--coatings", "single"});
  ASSERT_EQ(t.status, 0) << t.err;
  EXPECT_NE(t.out.find("dgauss-50mm: 45 two-reflection ghosts, strongest first (coatings single"),
            std::string::npos)
      << t.out;
  const int first = ghosts[0]["surfaces"][0], second = ghosts[0]["surfaces"][1];
  EXPECT_NE(t.out.find(fmt::format("{:>5},{:<3}", first, second)), std::string::npos) << t.out;
}

TEST(LensGhostsCli, BadArgumentsAreOneLine) {
  const RunResult coating = runLensrt({"lens", "ghosts", "dgauss-50mm", "--coatings", "triple"});
  EXPECT_EQ(coating.status, 2);
  EXPECT_EQ(std::count(coating.err.begin(), coating.err.end(), '\n'), 1) << coating.err;
  EXPECT_NE(coating.err.find("--coatings"), std::string::npos) << coating.err;
  const RunResult missing = runLensrt({"lens", "ghosts", "no-such-lens"});
  EXPECT_NE(missing.status, 0);
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  EXPECT_NE(missing.err.find("no-such-lens"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace lensrt
