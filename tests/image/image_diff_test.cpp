#include "image/image_diff.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image_test_util.h"

namespace lensrt {
namespace {

// 10x10 RGB at 0.5 with one value, G at (3,7), raised by 0.1.
struct SinglePixelChange : ::testing::Test {
  Image a = test::constantImage(10, 10, {"R", "G", "B"}, 0.5f);
  Image b = a;
  void SetUp() override { b.at(3, 7, 1) = 0.6f; }
};

TEST_F(SinglePixelChange, MetricsMatchHandComputedValues) {
  const DiffReport r = diffImages(a, b, {});
  const double d = double(0.6f) - 0.5;  // the float step actually stored
  const DiffStats& all = r.overall;
  EXPECT_DOUBLE_EQ(all.maxError, d);
  EXPECT_EQ(all.maxX, 3);
  EXPECT_EQ(all.maxY, 7);
  EXPECT_EQ(all.maxChannel, "G");
  EXPECT_DOUBLE_EQ(all.meanError, d / 300);
  EXPECT_DOUBLE_EQ(all.rmse, std::sqrt(d * d / 300));
  EXPECT_NEAR(all.psnr, 10 * std::log10(300 / (d * d)), 1e-9);  // ~44.77 dB
  EXPECT_NEAR(all.meanRelativeError, d / ((0.5 + 0.5 + d) / 2) / 300, 1e-12);
  EXPECT_EQ(all.failCount, 1);
  EXPECT_DOUBLE_EQ(all.failPercent, 1.0);

  ASSERT_EQ(r.channels.size(), 3u);
  EXPECT_EQ(r.channels[0].maxError, 0.0);
  EXPECT_TRUE(std::isinf(r.channels[0].psnr));
  EXPECT_DOUBLE_EQ(r.channels[1].meanError, d / 100);
  EXPECT_DOUBLE_EQ(r.channels[1].rmse, d / 10);
  EXPECT_EQ(r.channels[1].failCount, 1);
}

TEST_F(SinglePixelChange, VerdictsFollowIdiffRules) {
  EXPECT_EQ(diffImages(a, b, {}).verdict, DiffVerdict::Fail);
  DiffThresholds t;
  t.failPercent = 1.0;  // one pixel in 100 is not more than 1%
  EXPECT_EQ(diffImages(a, b, t).verdict, DiffVerdict::Warn);
  t.warnPercent = 1.0;
  EXPECT_EQ(diffImages(a, b, t).verdict, DiffVerdict::Pass);
  t.hardFail = 0.05;  // any single value over it fails regardless
  EXPECT_EQ(diffImages(a, b, t).verdict, DiffVerdict::Fail);
  t.hardFail = 1;
  t.hardWarn = 0.05;
  EXPECT_EQ(diffImages(a, b, t).verdict, DiffVerdict::Warn);

  DiffThresholds relative;  // 0.1 / 0.55 = 0.18 relative: under 0.2, over 0.15
  relative.failRelative = 0.2;
  relative.warnRelative = 0.2;
  EXPECT_EQ(diffImages(a, b, relative).verdict, DiffVerdict::Pass);
  relative.failRelative = 0.15;
  EXPECT_EQ(diffImages(a, b, relative).verdict, DiffVerdict::Fail);

  DiffThresholds loose;
  loose.fail = 0.2;
  loose.warn = 0.05;
  EXPECT_EQ(diffImages(a, b, loose).verdict, DiffVerdict::Warn);
  loose.warn = 0.2;
  EXPECT_EQ(diffImages(a, b, loose).verdict, DiffVerdict::Pass);
}

TEST(ImageDiff, IdenticalImagesPassWithInfinitePsnr) {
  Image a = test::constantImage(4, 3, {"R", "G", "B", "A"}, 0.25f);
  a.at(1, 1, 0) = std::numeric_limits<float>::quiet_NaN();
  a.at(2, 1, 0) = std::numeric_limits<float>::infinity();
  const DiffReport r = diffImages(a, a, {});
  EXPECT_EQ(r.verdict, DiffVerdict::Pass);
  EXPECT_EQ(r.overall.maxError, 0.0);
  EXPECT_TRUE(std::isinf(r.overall.psnr));
}

TEST(ImageDiff, NanAgainstANumberIsAnInfiniteError) {
  const Image a = test::constantImage(2, 2, {"R"}, 1.0f);
  Image b = a;
  b.at(1, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  DiffThresholds t;
  t.failPercent = 50;  // one pixel of four would be allowed...
  t.hardFail = 1e30;   // ...but not an infinite error
  const DiffReport r = diffImages(a, b, t);
  EXPECT_TRUE(std::isinf(r.overall.maxError));
  EXPECT_EQ(r.verdict, DiffVerdict::Fail);
  EXPECT_TRUE(std::isinf(perPixelMaxError(a, b)[1]));
}

TEST(ImageDiff, ChannelsAreMatchedByName) {
  Image a(2, 1, {"R", "G", "depth.Z"});
  Image b(2, 1, {"depth.Z", "R", "G"});
  for (int x = 0; x < 2; ++x) {
    a.at(x, 0, 0) = b.at(x, 0, 1) = 0.1f * x;
    a.at(x, 0, 1) = b.at(x, 0, 2) = 0.2f;
    a.at(x, 0, 2) = b.at(x, 0, 0) = 7.0f + x;
  }
  EXPECT_FALSE(incomparableReason(a, b));
  EXPECT_EQ(diffImages(a, b, {}).overall.maxError, 0.0);
}

TEST(ImageDiff, DifferentSizesOrChannelsAreNotComparable) {
  const Image a = test::constantImage(4, 3, {"R", "G", "B"}, 0);
  const auto size = incomparableReason(a, test::constantImage(3, 4, {"R", "G", "B"}, 0));
  ASSERT_TRUE(size);
  EXPECT_NE(size->find("4x3 versus 3x4"), std::string::npos) << *size;
  const auto channels = incomparableReason(a, test::constantImage(4, 3, {"R", "G", "B", "A"}, 0));
  ASSERT_TRUE(channels);
  EXPECT_NE(channels->find("R,G,B versus R,G,B,A"), std::string::npos) << *channels;
  EXPECT_THROW(diffImages(a, test::constantImage(4, 3, {"X", "Y", "Z"}, 0), {}), std::invalid_argument);
}

TEST(ImageDiff, PerPixelMaxErrorTakesTheLargestChannel) {
  const Image a = test::constantImage(2, 1, {"R", "G"}, 0.0f);
  Image b = a;
  b.at(0, 0, 0) = 0.25f;
  b.at(0, 0, 1) = -0.5f;
  b.at(1, 0, 1) = 0.125f;
  EXPECT_EQ(perPixelMaxError(a, b), (std::vector<float>{0.5f, 0.125f}));
}

}  // namespace
}  // namespace lensrt
