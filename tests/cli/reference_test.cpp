// docs/cli-reference.md is `lensrt options --markdown`: generated from the
// option table, it cannot go stale (tools/gen-reference rewrites it).
#include <gtest/gtest.h>

#include "cli/cli_util.h"

namespace lensrt::cli {
namespace {

TEST(Reference, TheCommittedPageIsTheOptionTables) {
  const RunResult r = runLensrt({"options", "--markdown"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, readFile(std::filesystem::path(LENSRT_SOURCE_DIR) / "docs" / "cli-reference.md"))
      << "docs/cli-reference.md differs from the option table: run tools/gen-reference";
  EXPECT_NE(r.out.find("| `--fstop` | `fstop=` |"), std::string::npos);
}

TEST(Reference, OptionsListsEveryRowForPeople) {
  const RunResult r = runLensrt({"options"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("--focus METRES|auto|inf|KEYFRAMES  (Python focus=)"), std::string::npos) << r.out;
}

TEST(Reference, ASettingThatDoesNothingIsNamed) {
  TempDir dir;
  const RunResult r =
      runLensrt({"render", std::string(LENSRT_SOURCE_DIR) + "/scenes/dof_row.gltf", "--lens", "dgauss-50mm",
                 "--fstop", "1.4", "--res", "16x9", "--spp", "1", "-o", (dir / "x.png").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(
      r.err.find("lensrt: warning: --fstop does nothing with the pinhole's radiance film: it applies to "
                 "--camera thin, thick or lens"),
      std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("lensrt: warning: --lens gives the pinhole only its field of view"),
            std::string::npos);
}

}  // namespace
}  // namespace lensrt::cli
