// LENSRT_EMBREE_CONFIG is checked before Embree sees it: Embree 3 ignores an
// unknown key or ISA without a word.
#include "scene/embree_config.h"

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"

namespace lensrt {
namespace {

std::string refusal(const std::string& config) {
  try {
    checkEmbreeConfig(config);
  } catch (const UsageError& e) {
    EXPECT_EQ(e.option(), "LENSRT_EMBREE_CONFIG");
    return e.message();
  }
  return "";
}

TEST(EmbreeConfig, TheDocumentedKeysAndValuesPass) {
  for (const char* ok :
       {"isa=sse4.2", "isa=sse2", "max_isa=avx2", "isa=avx512", "verbose=1", "verbose=0", "threads=0",
        "threads=8,user_threads=2", "set_affinity=1", "start_threads=0", "hugepages=1",
        "frequency_level=simd256", "isa=sse4.2, verbose=1", " isa = avx ", "tri_accel=bvh4.triangle4v"})
    EXPECT_EQ(refusal(ok), "") << ok;
}

TEST(EmbreeConfig, AnUnknownKeyOrValueNamesItAndTheVariable) {
  EXPECT_EQ(refusal("isa=sse9"),
            "isa takes one of sse2, sse4.2, avx, avx2, avx512, got 'sse9' in 'isa=sse9'");
  EXPECT_NE(refusal("nonsense").find("expected KEY=VALUE entries separated by commas"), std::string::npos);
  EXPECT_NE(refusal("isa=avx2,colour=red").find("unknown key 'colour'"), std::string::npos);
  EXPECT_EQ(refusal("verbose=x"), "verbose takes 0 to 4, got 'x' in 'verbose=x'");
  EXPECT_EQ(refusal("verbose=9"), "verbose takes 0 to 4, got '9' in 'verbose=9'");
  EXPECT_EQ(refusal("threads=-1"), "threads takes a number of threads, got '-1' in 'threads=-1'");
  EXPECT_EQ(refusal("hugepages=yes"), "hugepages takes 0 or 1, got 'yes' in 'hugepages=yes'");
  EXPECT_NE(refusal("isa="), "");
  EXPECT_NE(refusal("isa=avx2,"), "");  // a trailing comma is an empty entry
  EXPECT_NE(refusal("frequency_level=fast"), "");
}

}  // namespace
}  // namespace lensrt
