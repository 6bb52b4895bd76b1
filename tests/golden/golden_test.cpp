// Golden-image regression: every case of cases.txt rendered with a seed other
// than its reference's must be consistent with the reference under the
// noise-aware diff (false-alarm rate 1e-3 per image, see
// src/image/noise_aware_diff.h). On failure the render and a |t| heatmap are
// kept for inspection.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>

#include "golden/golden_util.h"

namespace lensrt::golden {
namespace {

class GoldenImage : public ::testing::TestWithParam<GoldenCase> {};

// Where failing renders are kept; printed in the failure message.
std::filesystem::path failureDir() {
  return std::filesystem::temp_directory_path() / "lensrt-golden-failures";
}

TEST_P(GoldenImage, MatchesReference) {
  const GoldenCase& c = GetParam();
  ASSERT_TRUE(std::filesystem::exists(referencePath(c)))
      << referencePath(c) << " is missing: run tools/update-references " << c.name;
  const TempDir dir;
  const auto render = dir / (c.name + ".exr");
  const RunResult r = renderCase(c, kTestSeed, render);
  ASSERT_EQ(r.status, 0) << r.err;

  const RunResult d = diffWithReference(c, render);
  if (d.status != 0) {
    std::filesystem::create_directories(failureDir());
    const auto kept = failureDir() / (c.name + ".exr"), heatmap = failureDir() / (c.name + "-t.png");
    std::filesystem::copy_file(render, kept, std::filesystem::copy_options::overwrite_existing);
    diffWithReference(c, render, {"--heatmap", heatmap.string()});
    ADD_FAILURE() << c.name << " differs from its reference (lensrt diff exit " << d.status << "):\n"
                  << d.out << d.err << "kept the render as " << kept << " and the |t| map as " << heatmap
                  << "; if the change is intended, run tools/update-references " << c.name;
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, GoldenImage, ::testing::ValuesIn(loadCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

TEST(GoldenCases, ParseNamesScenesAndArguments) {
  const TempDir dir;
  const auto file = dir / "cases.txt";
  {
    std::ofstream out(file);
    out << "# comment\n\n  a  x.gltf --res 8x8   # trailing comment\nb y.gltf\n";
  }
  const auto cases = loadCases(file);
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].name, "a");
  EXPECT_EQ(cases[0].scene, "x.gltf");
  EXPECT_EQ(cases[0].args, (std::vector<std::string>{"--res", "8x8"}));
  EXPECT_TRUE(cases[1].args.empty());
  {
    std::ofstream out(file);
    out << "lonely\n";
  }
  EXPECT_THROW(loadCases(file), std::runtime_error);
}

TEST(GoldenCases, EveryCaseHasAUniqueNameAndAnExistingScene) {
  std::set<std::string> names;
  for (const auto& c : loadCases()) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate case " << c.name;
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(LENSRT_SOURCE_DIR) / "scenes" / c.scene))
        << c.name << ": " << c.scene;
  }
  EXPECT_GE(names.size(), 4u);
}

}  // namespace
}  // namespace lensrt::golden
