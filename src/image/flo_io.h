// Middlebury / Sintel optical flow files (.flo), the format flow benchmarks
// read: the tag "PIEH" (the float 202021.25), width and height as int32,
// then row by row, top to bottom, each pixel's (u, v) as float32, all
// little-endian (x right, y down, in pixels).
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"

namespace lensrt {

inline constexpr float kFloTag = 202021.25f;

// Writes channels `u` and `v` of `image` (its width x height) to `file`.
// Throws InputError(file, ...) when it cannot be written, std::invalid_argument
// when the image lacks a channel.
void writeFlo(const std::filesystem::path& file, const Image& image, const std::string& u,
              const std::string& v);

}  // namespace lensrt
