#include "core/vec.h"

#include <gtest/gtest.h>

#include <limits>

namespace lensrt {
namespace {

TEST(UnitVector, IsUnitForTinyAndHugeVectors) {
  // Squared lengths that underflow to denormals or zero, and overflow to inf.
  for (const float scale : {1.0f, 1e-20f, 1e-25f, 1e-30f, 1e19f, 1e30f, 3e38f}) {
    const auto u = unitVector(Vec3f{3.0f, 0.0f, 4.0f} * (scale / 4.0f));
    ASSERT_TRUE(u) << scale;
    EXPECT_NEAR(u->x, 0.6f, 1e-6f) << scale;
    EXPECT_NEAR(u->z, 0.8f, 1e-6f) << scale;
  }
}

TEST(UnitVector, ZeroAndNonFiniteHaveNone) {
  EXPECT_FALSE(unitVector(Vec3f{0, 0, 0}));
  EXPECT_FALSE(unitVector(Vec3f{std::numeric_limits<float>::infinity(), 0, 0}));
  EXPECT_FALSE(unitVector(Vec3f{std::numeric_limits<float>::quiet_NaN(), 1, 0}));
}

TEST(UnitVector, OrdinaryVectorsMatchNormalize) {
  const Vec3f v{0.3f, -2.0f, 7.5f};
  const auto u = unitVector(v);
  ASSERT_TRUE(u);
  const Vec3f n = normalize(v);
  EXPECT_EQ(u->x, n.x);
  EXPECT_EQ(u->y, n.y);
  EXPECT_EQ(u->z, n.z);
}

}  // namespace
}  // namespace lensrt
