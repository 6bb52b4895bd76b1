#include "image/contact_sheet.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "image/text.h"

namespace lensrt {
namespace {

constexpr int kPadding = 8;
constexpr float kBackground = 0.02f;
const TextStyle kCaption{14, {0.9f, 0.9f, 0.9f}};
constexpr int kLineGap = 4;

std::array<int, 3> shownChannels(const Image& image) {
  const std::array<int, 3> rgb{image.channelIndex("R"), image.channelIndex("G"), image.channelIndex("B")};
  if (rgb[0] >= 0 && rgb[1] >= 0 && rgb[2] >= 0) return rgb;
  if (image.channelCount() == 1) return {0, 0, 0};
  throw std::invalid_argument("makeContactSheet: an image has neither R,G,B nor a single channel");
}

}  // namespace

Image makeContactSheet(const std::vector<LabelledImage>& items, int columns) {
  if (items.empty()) throw std::invalid_argument("makeContactSheet: no images");
  if (columns < 1) throw std::invalid_argument("makeContactSheet: columns must be at least 1");
  columns = std::min<int>(columns, int(items.size()));
  const int rows = (int(items.size()) + columns - 1) / columns;

  int imageWidth = 0, imageHeight = 0, captionWidth = 0;
  std::size_t captionLines = 0;
  for (const auto& item : items) {
    imageWidth = std::max(imageWidth, item.image.width);
    imageHeight = std::max(imageHeight, item.image.height);
    captionLines = std::max(captionLines, item.lines.size());
    for (const auto& line : item.lines) captionWidth = std::max(captionWidth, textWidth(line, kCaption));
  }
  const int lineHeight = kCaption.size + kLineGap;
  const int cellWidth = std::max(imageWidth, captionWidth) + kPadding;
  const int cellHeight = imageHeight + int(captionLines) * lineHeight + 2 * kPadding;

  Image sheet(columns * cellWidth + kPadding, rows * cellHeight + kPadding, {"R", "G", "B"});
  std::fill(sheet.pixels.begin(), sheet.pixels.end(), kBackground);
  for (std::size_t i = 0; i < items.size(); ++i) {
    const Image& image = items[i].image;
    const std::array<int, 3> source = shownChannels(image);
    const int x0 = kPadding + int(i % columns) * cellWidth;
    const int y0 = kPadding + int(i / columns) * cellHeight;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c) sheet.at(x0 + x, y0 + y, c) = image.at(x, y, source[c]);
    int textY = y0 + image.height + kPadding / 2;
    for (const auto& line : items[i].lines) {
      drawText(sheet, x0, textY, line, kCaption);
      textY += lineHeight;
    }
  }
  return sheet;
}

}  // namespace lensrt
