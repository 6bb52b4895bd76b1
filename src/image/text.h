// Text labels drawn into images (heatmap scales, contact-sheet captions).
//
// Drawn with stb_truetype from DejaVu Sans Mono (Debian
// package fonts-dejavu-core). When that font cannot be found, a built-in
// 3x5 pixel font (digits, capitals and common punctuation, scaled up) is
// used instead, so labels never silently disappear.
#pragma once

#include <array>
#include <string>

#include "image/image.h"

namespace lensrt {

using Rgb = std::array<float, 3>;

struct TextStyle {
  int size = 14;  // pixel height of a line
  Rgb colour{1.0f, 1.0f, 1.0f};
};

// Draws `text` with its top-left corner at (x, y) into channels R,G,B of
// `image`, clipped to the image. Returns the width drawn, in pixels.
int drawText(Image& image, int x, int y, const std::string& text, const TextStyle& style = {});

// The width `text` takes when drawn with `style`.
int textWidth(const std::string& text, const TextStyle& style = {});

// True when the FreeType font is available (false: the bitmap fallback).
bool hasVectorFont();

}  // namespace lensrt
