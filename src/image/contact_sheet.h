// A grid of images with text captions, for side-by-side comparisons of
// camera models and settings (`lensrt compare`).
#pragma once

#include <string>
#include <vector>

#include "image/image.h"

namespace lensrt {

struct LabelledImage {
  Image image;                     // its R,G,B are shown (a single channel as grey)
  std::vector<std::string> lines;  // caption: model name, then settings lines
};

// Cells are as large as the largest image plus room for the longest caption;
// images sit top-left in their cell with the caption below. Linear RGB out,
// dark background, light text. Throws std::invalid_argument for no images,
// columns < 1, or an image without R,G,B or a single channel.
Image makeContactSheet(const std::vector<LabelledImage>& items, int columns);

}  // namespace lensrt
