// Writing the image formats whose encoder is lensrt's OpenImageIO plugin
// (image/oiio_plugin.h; the formats: image/output_formats.h). Like the
// .png/.jpg previews, R,G,B only (no alpha, no AOVs), display-referred
// except Cineon log (DPX). TIFF files carry the metadata as their
// ImageDescription text; every file names lensrt as its Software where the
// format has the field.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/output_formats.h"
#include "image/preview_values.h"

namespace lensrt {

// Writes `image`'s channels `rgb` (three indices) to `temporary`, the file
// that will be renamed to `file` (which names it in errors). Throws
// InputError(file, reason), also when the plugin cannot be loaded.
// `display`: the previews' OpenColorIO display transform (not for DPX).
void writeWithPlugin(const std::filesystem::path& file, const std::filesystem::path& temporary,
                     const OutputFormat& format, const Image& image, const std::vector<int>& rgb,
                     const ImageMetadata& metadata, const std::optional<DisplayTransform>& display);

}  // namespace lensrt
