#include "image/text.h"

#include <stb_truetype.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace lensrt {
namespace {

// DejaVu Sans Mono where Debian (fonts-dejavu-core), Fedora and Arch put it.
constexpr const char* kFontFiles[] = {
    "/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf",
    "/usr/share/fonts/dejavu-sans-mono-fonts/DejaVuSansMono.ttf",
    "/usr/share/fonts/TTF/DejaVuSansMono.ttf",
};

// The font file's bytes and stb_truetype's view of them (which points into
// the bytes, so the two live together and are never copied).
class Font {
 public:
  static std::optional<Font> load() {
    for (const char* path : kFontFiles) {
      std::ifstream in(path, std::ios::binary);
      if (!in) continue;
      Font font;
      font.bytes_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      const auto* data = reinterpret_cast<const unsigned char*>(font.bytes_.data());
      const int offset = stbtt_GetFontOffsetForIndex(data, 0);
      if (offset >= 0 && stbtt_InitFont(&font.info_, data, offset)) return font;
    }
    return std::nullopt;
  }
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;
  Font(Font&& other) noexcept : bytes_(std::move(other.bytes_)), info_(other.info_) { rebind(); }
  Font& operator=(Font&&) = delete;

  // `size` pixels per em, as FreeType's pixel size (what OpenImageIO used).
  float scale(int size) const { return stbtt_ScaleForMappingEmToPixels(&info_, float(size)); }
  int advance(int codepoint, float scale) const {
    int advanceWidth = 0, leftBearing = 0;
    stbtt_GetCodepointHMetrics(&info_, codepoint, &advanceWidth, &leftBearing);
    return int(std::lround(advanceWidth * scale));
  }
  // The glyph's ink box relative to the pen on the baseline (y down).
  void box(int codepoint, float scale, int& x0, int& y0, int& x1, int& y1) const {
    stbtt_GetCodepointBitmapBox(&info_, codepoint, scale, scale, &x0, &y0, &x1, &y1);
  }
  std::vector<unsigned char> coverage(int codepoint, float scale, int width, int height) const {
    std::vector<unsigned char> bitmap(std::size_t(width) * height, 0);
    stbtt_MakeCodepointBitmap(&info_, bitmap.data(), width, height, width, scale, scale, codepoint);
    return bitmap;
  }

 private:
  Font() = default;
  // stb_truetype keeps a pointer to the data; after a move it must point
  // into this object's bytes (a moved std::string may relocate short data).
  void rebind() {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data());
    stbtt_InitFont(&info_, data, stbtt_GetFontOffsetForIndex(data, 0));
  }
  std::string bytes_;
  stbtt_fontinfo info_{};
};

// Labels are ASCII or UTF-8 (units such as "µm"); a broken sequence shows
// as U+FFFD.
std::vector<int> codepoints(const std::string& text) {
  std::vector<int> out;
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const int extra = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xe ? 2 : (c >> 3) == 0x1e ? 3 : -1;
    if (extra < 0 || i + std::size_t(extra) >= text.size()) {
      out.push_back(0xfffd);
      ++i;
      continue;
    }
    int cp = extra == 0 ? c : c & (0x3f >> extra);
    bool valid = true;
    for (int k = 1; k <= extra; ++k) {
      const unsigned char n = static_cast<unsigned char>(text[i + k]);
      valid = valid && (n & 0xc0) == 0x80;
      cp = (cp << 6) | (n & 0x3f);
    }
    out.push_back(valid ? cp : 0xfffd);
    i += valid ? std::size_t(extra) + 1 : 1;
  }
  return out;
}

int vectorTextWidth(const Font& font, const std::vector<int>& text, float scale) {
  int width = 0;
  for (const int cp : text) width += font.advance(cp, scale);
  return width;
}

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
  return Font::load().has_value();
}

int textWidth(const std::string& text, const TextStyle& style) {
  const std::optional<Font> font = Font::load();
  return font ? vectorTextWidth(*font, codepoints(text), font->scale(style.size))
              : int(text.size()) * 4 * bitmapScale(style.size);
}

int drawText(Image& image, int x, int y, const std::string& text, const TextStyle& style) {
  const int rgb[3] = {image.channelIndex("R"), image.channelIndex("G"), image.channelIndex("B")};
  if (rgb[0] < 0 || rgb[1] < 0 || rgb[2] < 0 || text.empty()) return 0;
  const std::optional<Font> font = Font::load();
  if (!font) return drawBitmapText(image, rgb, x, y, text, style);

  // The baseline sits a fixed ascent below y (the top of "Ag|" plus one
  // pixel) so that labels line up whatever letters they hold.
  const float scale = font->scale(style.size);
  int top = 0;
  for (const int cp : codepoints("Ag|")) {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    font->box(cp, scale, x0, y0, x1, y1);
    top = std::min(top, y0);
  }
  const int baseline = y - top + 1;
  int penX = x;
  for (const int cp : codepoints(text)) {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    font->box(cp, scale, x0, y0, x1, y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      const std::vector<unsigned char> ink = font->coverage(cp, scale, w, h);
      for (int gy = 0; gy < h; ++gy)
        for (int gx = 0; gx < w; ++gx)
          blendPixel(image, rgb, penX + x0 + gx, baseline + y0 + gy, style.colour,
                     float(ink[std::size_t(gy) * w + gx]) / 255.0f);
    }
    penX += font->advance(cp, scale);
  }
  return penX - x;
}

}  // namespace lensrt
