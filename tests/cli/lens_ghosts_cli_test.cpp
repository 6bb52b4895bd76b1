// `lensrt lens ghosts`: the listing's text and JSON agree with the library
// (optics/ghosts, checked against closed forms in tests/optics), surfaces
// are numbered from 1, and bad arguments get one line and status 2.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

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

// `lens diagram --ghost I,J` draws the ghost's bundle: the rays the
// apertures pass, as polylines in their own group, with a legend line.
TEST(LensGhostsCli, TheDiagramDrawsAGhostPath) {
  const cli::TempDir dir;
  const std::string svg = (dir / "g.svg").string();
  const RunResult r = runLensrt({"lens", "diagram", "dgauss-50mm", "-o", svg, "--ghost", "10,2"});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = cli::readFile(svg);
  const std::size_t group = text.find("class=\"ghost\"");
  ASSERT_NE(group, std::string::npos);
  const std::size_t groupEnd = text.find("</g>", group);
  int rays = 0;
  for (std::size_t at = text.find("<polyline", group); at < groupEnd; at = text.find("<polyline", at + 1))
    ++rays;
  EXPECT_GE(rays, 8);  // of 15 across the front element: the 10,2 ghost passes most of them
  EXPECT_NE(text.find("ghost 10,2: an axial bundle reflected at surface 10, then at 2"), std::string::npos);
  EXPECT_EQ(runLensrt({"lens", "diagram", "dgauss-50mm", "-o", svg}).status, 0);
  EXPECT_EQ(cli::readFile(svg).find("class=\"ghost\""), std::string::npos);
}

TEST(LensGhostsCli, ABadGhostIsOneLine) {
  const cli::TempDir dir;
  const std::string svg = (dir / "g.svg").string();
  for (const auto& [arg, says] : std::vector<std::pair<std::string, std::string>>{
           {"6,2", "surface 6 reflects nothing (it is the stop)"},
           {"2,10", "expected I > J, got 2,10 (try 10,2)"},
           {"12,1", "surface 12 is not one of the lens's 11 surfaces"},
           {"10,", "expected two surface numbers I,J"},
           {"ten,two", "expected two surface numbers I,J"}}) {
    const RunResult r = runLensrt({"lens", "diagram", "dgauss-50mm", "-o", svg, "--ghost", arg});
    EXPECT_EQ(r.status, 2) << arg;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("lensrt: error: --ghost: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(svg)) << arg;
  }
}

}  // namespace
}  // namespace lensrt
