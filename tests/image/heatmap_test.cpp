#include "image/heatmap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "image/contact_sheet.h"
#include "image/image_io.h"
#include "image/srgb.h"
#include "image/text.h"
#include "image_test_util.h"

namespace lensrt {
namespace {

// Matplotlib's viridis end points in sRGB: 0 -> #440154, 1 -> #fde725.
constexpr float kViridisLow[3] = {0x44 / 255.0f, 0x01 / 255.0f, 0x54 / 255.0f};
constexpr float kViridisHigh[3] = {0xfd / 255.0f, 0xe7 / 255.0f, 0x25 / 255.0f};

void expectSrgbNear(const Image& image, int x, int y, const float (&srgb)[3]) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(srgbEncode(image.at(x, y, c)), srgb[c], 0.02f) << "channel " << c;
}

TEST(Heatmap, MapsZeroAndMaxToViridisEndsAndAddsAColourBar) {
  std::vector<float> error(40 * 30, 0.0f);
  error[5 * 40 + 7] = 0.5f;
  error[6 * 40 + 7] = 2.0f;  // over the scale: saturates
  error[7 * 40 + 7] = std::numeric_limits<float>::infinity();
  HeatmapOptions options;
  options.scaleMax = 0.5;
  const Image map = makeHeatmap(error, 40, 30, options);
  EXPECT_GT(map.width, 40 + 16);  // the bar and its labels sit to the right
  EXPECT_GE(map.height, 30);
  expectSrgbNear(map, 0, 0, kViridisLow);
  expectSrgbNear(map, 7, 5, kViridisHigh);
  expectSrgbNear(map, 7, 6, kViridisHigh);
  EXPECT_EQ(map.at(7, 7, 0), 1.0f);  // non-finite errors in magenta
  EXPECT_EQ(map.at(7, 7, 1), 0.0f);
}

TEST(Heatmap, AutomaticScaleIsTheLargestFiniteError) {
  const std::vector<float> error{0.0f, 0.25f, std::numeric_limits<float>::infinity(), 0.125f};
  EXPECT_EQ(heatmapScale(error, {}), 0.25);
  EXPECT_EQ(heatmapScale(std::vector<float>(4, 0.0f), {}), 1.0);
}

TEST(Heatmap, ScaleLabels) {
  EXPECT_EQ(formatScaleLabel(0.25), "0.25");
  EXPECT_EQ(formatScaleLabel(1.5e-5), "1.5e-05");
  EXPECT_EQ(formatScaleLabel(1234.0), "1.23e+03");
}

TEST(Heatmap, WrittenAsPng) {
  const test::ScratchDir dir;
  std::vector<float> error(64 * 48);
  for (std::size_t i = 0; i < error.size(); ++i) error[i] = float(i % 64) / 64.0f;
  const Image map = makeHeatmap(error, 64, 48);
  writeImage(dir / "heat.png", map, {});
  const Image back = readImage(dir / "heat.png");
  EXPECT_EQ(back.width, map.width);
  EXPECT_EQ(back.height, map.height);
}

int inkedPixels(const Image& image) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += image.at(x, y, 0) > 0.5f;
  return n;
}

TEST(Text, DrawsInkWithinItsWidth) {
  Image image = test::constantImage(120, 30, {"R", "G", "B"}, 0.0f);
  const int width = drawText(image, 4, 4, "0.125 f/2.8", TextStyle{14, {1, 1, 1}});
  EXPECT_GT(width, 20);
  EXPECT_EQ(width, textWidth("0.125 f/2.8", TextStyle{14, {1, 1, 1}}));
  EXPECT_GT(inkedPixels(image), 20);
  for (int y = 0; y < image.height; ++y)
    for (int x = 4 + width + 2; x < image.width; ++x) EXPECT_EQ(image.at(x, y, 0), 0.0f);
}

TEST(ContactSheet, LaysOutAGridWithCaptions) {
  std::vector<LabelledImage> items;
  for (int i = 0; i < 5; ++i)
    items.push_back(
        {test::constantImage(20 + i, 10, {"R", "G", "B"}, 0.1f * float(i + 1)), {"model", "f/2"}});
  const Image sheet = makeContactSheet(items, 3);
  // Two rows of three cells at least as large as the largest image (24x10).
  EXPECT_GE(sheet.width, 3 * 24);
  EXPECT_GE(sheet.height, 2 * 10);
  // Each image's value appears at the top-left of its cell.
  const int cellWidth = (sheet.width - 8) / 3, cellHeight = (sheet.height - 8) / 2;
  for (int i = 0; i < 5; ++i)
    EXPECT_FLOAT_EQ(sheet.at(8 + (i % 3) * cellWidth + 1, 8 + (i / 3) * cellHeight + 1, 0),
                    0.1f * float(i + 1));
  EXPECT_GT(inkedPixels(sheet), 20);  // captions are drawn
  EXPECT_THROW(makeContactSheet({}, 2), std::invalid_argument);
  EXPECT_THROW(makeContactSheet(items, 0), std::invalid_argument);
}

}  // namespace
}  // namespace lensrt
