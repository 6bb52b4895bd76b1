// LENSRT_EMBREE_CONFIG on the command line: a bad value is a usage error
// naming the variable (exit 2); an acceleration structure Embree refuses is an
// error that names it too (exit 1).
#include <gtest/gtest.h>
#include <stdlib.h>

#include <string>

#include "cli/cli_util.h"

namespace lensrt {
namespace {

using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

RunResult renderWith(const std::string& config, const TempDir& dir) {
  setenv("LENSRT_EMBREE_CONFIG", config.c_str(), 1);
  const RunResult r = runLensrt({"render", std::string(LENSRT_SOURCE_DIR) + "/scenes/furnace.gltf", "--res",
                                 "8x8", "--spp", "1", "-q", "-o", (dir / "a.exr").string()});
  unsetenv("LENSRT_EMBREE_CONFIG");
  return r;
}

TEST(EmbreeConfigCli, BadValuesNameTheVariable) {
  const TempDir dir;
  const RunResult isa = renderWith("isa=sse9", dir);
  EXPECT_EQ(isa.status, 2);
  EXPECT_EQ(
      isa.err,
      "lensrt: error: LENSRT_EMBREE_CONFIG: isa takes one of sse2, sse4.2, avx, avx2, avx512, got 'sse9' in "
      "'isa=sse9'\n");
  EXPECT_EQ(renderWith("nonsense", dir).status, 2);
  const RunResult accel = renderWith("tri_accel=foo", dir);
  EXPECT_EQ(accel.status, 1);
  EXPECT_NE(
      accel.err.find("unknown triangle acceleration structure foo (LENSRT_EMBREE_CONFIG='tri_accel=foo')"),
      std::string::npos)
      << accel.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.exr"));
  EXPECT_EQ(renderWith("isa=sse4.2,verbose=0", dir).status, 0);
}

}  // namespace
}  // namespace lensrt
