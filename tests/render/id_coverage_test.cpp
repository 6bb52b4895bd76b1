// The ID AOVs' hashing and ranking against the Cryptomatte specification's
// published values (not the code's own output).
#include "render/id_coverage.h"

#include <gtest/gtest.h>

#include <bit>

#include "core/murmur_hash.h"

namespace lensrt {
namespace {

TEST(Cryptomatte, HashesMatchTheSpecification) {
  EXPECT_EQ(murmurHash3X86_32("bunny"), 0x13851a76u);
  EXPECT_EQ(murmurHash3X86_32("default"), 0x42c9679fu);
  EXPECT_EQ(murmurHash3X86_32(""), 0u);  // MurmurHash3 of nothing with seed 0
}

TEST(Cryptomatte, ExponentStaysInOneTo254) {
  for (const std::uint32_t h : {0x00012345u, 0x807fffffu, 0x7f800001u, 0xff812345u, 0x13851a76u}) {
    const std::uint32_t exponent = (cryptomatteIdBits(h) >> 23) & 255;
    EXPECT_GE(exponent, 1u) << std::hex << h;
    EXPECT_LE(exponent, 254u) << std::hex << h;
  }
  EXPECT_EQ(cryptomatteIdBits(0x13851a76u), 0x13851a76u);  // a normal float is kept
}

TEST(Cryptomatte, RanksSumToOneAndOrderByCoverage) {
  IdCoverage px;
  const std::uint32_t a = cryptomatteIdBits(murmurHash3X86_32("a")),
                      b = cryptomatteIdBits(murmurHash3X86_32("b"));
  for (int i = 0; i < 5; ++i) px.add(a, 3, a, 0);
  for (int i = 0; i < 2; ++i) px.add(b, 7, b, 1);
  px.add(0, -1, 0, -1);  // one background sample
  float r[2 * kCryptoRanks];
  px.writeRanks(false, r);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(r[0]), a);
  EXPECT_FLOAT_EQ(r[1], 5.0f / 8);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(r[2]), b);
  EXPECT_FLOAT_EQ(r[3], 2.0f / 8);
  EXPECT_FLOAT_EQ(r[1] + r[3] + r[5] + r[7] + r[9] + r[11], 1.0f);
  EXPECT_EQ(px.topNode(), 3);
}

}  // namespace
}  // namespace lensrt
