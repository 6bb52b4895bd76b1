// Joining crops of a frame: exact copies, and one clear error for parts that
// overlap, leave a gap or do not match.
#include "image/image_merge.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace lensrt {
namespace {

Image part(int x0, int x1, int y0, int y1, std::vector<std::string> channels = {"R", "A"}) {
  Image im(x1 - x0, y1 - y0, std::move(channels));
  im.originX = x0;
  im.originY = y0;
  im.frameWidth = 4;
  im.frameHeight = 3;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x)
      for (int c = 0; c < int(im.channelCount()); ++c)
        im.at(x, y, c) = float((y0 + y) * 100 + (x0 + x) * 10 + c);
  return im;
}

std::string mergeError(const std::vector<Image>& parts) {
  std::vector<std::string> names;
  // Appended, not "p" + std::to_string(i): GCC 12's false -Wstringop-overflow (bug 105329).
  for (std::size_t i = 0; i < parts.size(); ++i)
    names.push_back(std::string("p").append(std::to_string(i)).append(".exr"));
  try {
    mergeImageParts(parts, names);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ImageMerge, PartsAreCopiedToTheirPlace) {
  // Channels in another order in one part: matched by name.
  Image b = part(0, 4, 1, 3);
  Image swapped(b.width, b.height, {"A", "R"});
  swapped.originX = 0;
  swapped.originY = 1;
  swapped.frameWidth = 4;
  swapped.frameHeight = 3;
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x) {
      swapped.at(x, y, 0) = b.at(x, y, 1);
      swapped.at(x, y, 1) = b.at(x, y, 0);
    }
  const std::vector<Image> parts{part(0, 4, 0, 1), swapped};
  const std::vector<std::string> names{"a", "b"};
  const Image whole = mergeImageParts(parts, names);
  ASSERT_EQ(whole.width, 4);
  ASSERT_EQ(whole.height, 3);
  EXPECT_TRUE(whole.isWholeFrame());
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(whole.at(x, y, 0), float(y * 100 + x * 10));
      EXPECT_EQ(whole.at(x, y, 1), float(y * 100 + x * 10 + 1));
    }
}

TEST(ImageMerge, OverlapGapAndMismatchNameTheParts) {
  EXPECT_EQ(mergeError({part(0, 4, 0, 2), part(0, 4, 1, 3)}),
            "p0.exr and p1.exr overlap (both have pixel 0,1)");
  EXPECT_EQ(mergeError({part(0, 4, 0, 1), part(0, 4, 2, 3)}),
            "the parts leave a gap: no part has row 1, x 0..4 of the 4x3 frame");
  EXPECT_EQ(mergeError({part(0, 4, 0, 1), part(0, 4, 1, 3, {"R", "G"})}),
            "p1.exr has no channel A (p0.exr has)");
  Image other = part(0, 4, 1, 3);
  other.frameWidth = 5;
  EXPECT_EQ(mergeError({part(0, 4, 0, 1), other}), "p1.exr is part of a 5x3 frame, p0.exr of a 4x3 frame");
  EXPECT_NE(mergeError({}), "");
}

}  // namespace
}  // namespace lensrt
