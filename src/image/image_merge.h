// Assembling the parts of a frame (crops, tiles: images with a data window in
// the same display window) into the whole frame.
#pragma once

#include <span>
#include <string>

#include "image/image.h"

namespace lensrt {

// The frame the parts cover, pixels copied bit for bit. Every part must have
// the same frame size and channels (in any order: they are matched by name)
// and the parts must cover every pixel exactly once. Throws
// std::invalid_argument with one line naming the parts (by `names`, one per
// part) for a mismatch, an overlap or a gap.
Image mergeImageParts(std::span<const Image> parts, std::span<const std::string> names);

}  // namespace lensrt
