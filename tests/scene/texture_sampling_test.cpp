#include "scene/texture_sampling.h"

#include <gtest/gtest.h>

namespace lensrt {
namespace {

// 2x2 texture whose red channel is the texel's column and green its row.
Texture grid() {
  Texture t;
  t.width = 2;
  t.height = 2;
  t.texels = {{0, 0, 0, 1}, {1, 0, 0, 1}, {0, 1, 0, 1}, {1, 1, 0, 1}};
  return t;
}

TEST(TextureSampling, TexelCentresReturnTexels) {
  const Texture t = grid();
  EXPECT_EQ(sampleTexture(t, {0.25f, 0.25f}).x, 0.0f);
  EXPECT_EQ(sampleTexture(t, {0.75f, 0.25f}).x, 1.0f);
  EXPECT_EQ(sampleTexture(t, {0.75f, 0.75f}).y, 1.0f);  // v grows downward: row 1
}

TEST(TextureSampling, BilinearInterpolatesBetweenCentres) {
  Texture t = grid();
  t.wrapRepeatS = t.wrapRepeatT = false;
  const Vec4f c = sampleTexture(t, {0.5f, 0.375f});
  EXPECT_NEAR(c.x, 0.5f, 1e-6f);
  EXPECT_NEAR(c.y, 0.25f, 1e-6f);
}

TEST(TextureSampling, RepeatBlendsAcrossTheEdgeClampDoesNot) {
  Texture t = grid();
  // u = 0 lies halfway between the last column (wrapped) and the first.
  EXPECT_NEAR(sampleTexture(t, {0.0f, 0.25f}).x, 0.5f, 1e-6f);
  EXPECT_NEAR(sampleTexture(t, {1.25f, 0.25f}).x, 0.0f, 1e-6f);
  EXPECT_NEAR(sampleTexture(t, {-0.25f, 0.25f}).x, 1.0f, 1e-6f);
  t.wrapRepeatS = false;
  EXPECT_NEAR(sampleTexture(t, {0.0f, 0.25f}).x, 0.0f, 1e-6f);
  EXPECT_NEAR(sampleTexture(t, {7.0f, 0.25f}).x, 1.0f, 1e-6f);
}

TEST(TextureSampling, MirroredRepeatReflects) {
  Texture t = grid();
  t.mirrorS = true;
  t.nearest = true;
  EXPECT_EQ(sampleTexture(t, {1.25f, 0.25f}).x, 1.0f);  // mirrored: column 1 first
  EXPECT_EQ(sampleTexture(t, {1.75f, 0.25f}).x, 0.0f);
  EXPECT_EQ(sampleTexture(t, {2.25f, 0.25f}).x, 0.0f);
}

TEST(TextureSampling, NearestPicksContainingTexel) {
  Texture t = grid();
  t.nearest = true;
  EXPECT_EQ(sampleTexture(t, {0.49f, 0.1f}).x, 0.0f);
  EXPECT_EQ(sampleTexture(t, {0.51f, 0.1f}).x, 1.0f);
}

TEST(TextureSampling, EmptyOrNonFiniteIsSafe) {
  EXPECT_EQ(sampleTexture(Texture{}, {0.3f, 0.3f}), (Vec4f{1, 1, 1, 1}));
  const Vec4f c = sampleTexture(grid(), {std::numeric_limits<float>::quiet_NaN(), 1e30f});
  EXPECT_TRUE(std::isfinite(c.x) && std::isfinite(c.y));
}

}  // namespace
}  // namespace lensrt
