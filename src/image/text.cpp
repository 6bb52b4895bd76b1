#include "image/text.h"

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cctype>
#include <string_view>
#include <utility>

namespace lensrt {
namespace {

namespace OIIO = OIIO_NAMESPACE;

constexpr const char* kFont = "DejaVuSansMono";

// The fallback font: 3x5 cells, rows top to bottom, '#' = ink. Lower case
// is drawn as upper case; unknown characters as a box.
constexpr std::pair<char, std::string_view> kGlyphs[] = {
    {' ', "...|...|...|...|..."}, {'0', "###|#.#|#.#|#.#|###"}, {'1', ".#.|##.|.#.|.#.|###"},
    {'2', "###|..#|###|#..|###"}, {'3', "###|..#|.##|..#|###"}, {'4', "#.#|#.#|###|..#|..#"},
    {'5', "###|#..|###|..#|###"}, {'6', "###|#..|###|#.#|###"}, {'7', "###|..#|.#.|.#.|.#."},
    {'8', "###|#.#|###|#.#|###"}, {'9', "###|#.#|###|..#|###"}, {'.', "...|...|...|...|.#."},
    {',', "...|...|...|.#.|#.."}, {'-', "...|...|###|...|..."}, {'+', "...|.#.|###|.#.|..."},
    {'=', "...|###|...|###|..."}, {':', "...|.#.|...|.#.|..."}, {'/', "..#|..#|.#.|#..|#.."},
    {'%', "#.#|..#|.#.|#..|#.#"}, {'(', ".#.|#..|#..|#..|.#."}, {')', ".#.|..#|..#|..#|.#."},
    {'_', "...|...|...|...|###"}, {'x', "...|#.#|.#.|#.#|..."}, {'A', ".#.|#.#|###|#.#|#.#"},
    {'B', "##.|#.#|##.|#.#|##."}, {'C', ".##|#..|#..|#..|.##"}, {'D', "##.|#.#|#.#|#.#|##."},
    {'E', "###|#..|##.|#..|###"}, {'F', "###|#..|##.|#..|#.."}, {'G', ".##|#..|#.#|#.#|.##"},
    {'H', "#.#|#.#|###|#.#|#.#"}, {'I', "###|.#.|.#.|.#.|###"}, {'J', "..#|..#|..#|#.#|.#."},
    {'K', "#.#|#.#|##.|#.#|#.#"}, {'L', "#..|#..|#..|#..|###"}, {'M', "#.#|###|###|#.#|#.#"},
    {'N', "##.|#.#|#.#|#.#|#.#"}, {'O', ".#.|#.#|#.#|#.#|.#."}, {'P', "##.|#.#|##.|#..|#.."},
    {'Q', ".#.|#.#|#.#|##.|.##"}, {'R', "##.|#.#|##.|#.#|#.#"}, {'S', ".##|#..|.#.|..#|##."},
    {'T', "###|.#.|.#.|.#.|.#."}, {'U', "#.#|#.#|#.#|#.#|###"}, {'V', "#.#|#.#|#.#|#.#|.#."},
    {'W', "#.#|#.#|###|###|#.#"}, {'X', "#.#|#.#|.#.|#.#|#.#"}, {'Y', "#.#|#.#|.#.|.#.|.#."},
    {'Z', "###|..#|.#.|#..|###"},
};
constexpr std::string_view kUnknownGlyph = "###|#.#|#.#|#.#|###";

std::string_view glyphFor(char ch) {
  // 'x' keeps its own glyph (as in "2x3"); other letters map to capitals.
  const char key = ch == 'x' ? ch : char(std::toupper(static_cast<unsigned char>(ch)));
  for (const auto& [c, rows] : kGlyphs)
    if (c == key) return rows;
  return kUnknownGlyph;
}

int bitmapScale(int size) {
  return std::max(1, size / 7);
}

void blendPixel(Image& image, const int rgb[3], int x, int y, const Rgb& colour, float coverage) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || coverage <= 0) return;
  for (int c = 0; c < 3; ++c) {
    float& v = image.at(x, y, rgb[c]);
    v = v * (1 - coverage) + colour[c] * coverage;
  }
}

int drawBitmapText(Image& image, const int rgb[3], int x, int y, const std::string& text,
                   const TextStyle& style) {
  const int s = bitmapScale(style.size);
  int penX = x;
  for (const char ch : text) {
    const std::string_view rows = glyphFor(ch);
    for (int row = 0; row < 5; ++row)
      for (int col = 0; col < 3; ++col)
        if (rows[row * 4 + col] == '#')
          for (int dy = 0; dy < s; ++dy)
            for (int dx = 0; dx < s; ++dx)
              blendPixel(image, rgb, penX + col * s + dx, y + row * s + dy, style.colour, 1);
    penX += 4 * s;
  }
  return penX - x;
}

}  // namespace

bool hasVectorFont() {
  return OIIO::ImageBufAlgo::text_size("0", 12, kFont).defined();
}

int textWidth(const std::string& text, const TextStyle& style) {
  const OIIO::ROI roi = OIIO::ImageBufAlgo::text_size(text, style.size, kFont);
  return roi.defined() ? roi.xend : int(text.size()) * 4 * bitmapScale(style.size);
}

int drawText(Image& image, int x, int y, const std::string& text, const TextStyle& style) {
  const int rgb[3] = {image.channelIndex("R"), image.channelIndex("G"), image.channelIndex("B")};
  if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0 || text.empty()) return 0;
  const OIIO::ROI size = OIIO::ImageBufAlgo::text_size(text, style.size, kFont);
  if (!size.defined()) return drawBitmapText(image, rgb, x, y, text, style);

  // Render coverage into a small one-channel mask, then blend the colour
  // with it. The baseline sits a fixed ascent below y (measured on "Ag|")
  // so that labels line up whatever letters they hold.
  const OIIO::ROI line = OIIO::ImageBufAlgo::text_size("Ag|", style.size, kFont);
  const int ascent = -line.ybegin + 1;
  const int maskWidth = size.xend + 2, maskHeight = line.yend - line.ybegin + 3;
  OIIO::ImageBuf mask(OIIO::ImageSpec(maskWidth, maskHeight, 1, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::zero(mask);
  if (!OIIO::ImageBufAlgo::render_text(mask, 0, ascent, text, style.size, kFont, 1.0f))
    return drawBitmapText(image, rgb, x, y, text, style);
  for (int my = 0; my < maskHeight; ++my)
    for (int mx = 0; mx < maskWidth; ++mx) {
      float coverage = 0;
      mask.getpixel(mx, my, &coverage, 1);
      blendPixel(image, rgb, x + mx, y + my, style.colour, std::clamp(coverage, 0.0f, 1.0f));
    }
  return size.xend;
}

}  // namespace lensrt
