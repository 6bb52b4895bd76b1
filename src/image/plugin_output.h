// The image files lensrt writes through its OpenImageIO plugin
// (image/oiio_plugin.h), and how it encodes each. Like the .png/.jpg
// previews, R,G,B only (no alpha, no AOVs), display-referred except DPX:
//   .tif/.tiff   16-bit sRGB (each value clamped to [0,1], the sRGB curve), ZIP
//   .jp2/.j2k    16-bit sRGB, lossless JPEG 2000 (at least 32x32 pixels)
//   .webp        8-bit sRGB, lossy at quality 95 with chroma at half
//                resolution, as WebP's lossy mode has it (OpenImageIO 2.4's
//                lossless mode halves the chroma too, so it is not used)
//   .dpx         10-bit Cineon log (image/cineon.h): scene-linear 1.0 at code
//                685, highlights kept up to 13.5, for grading and film outs
// TIFF files carry the metadata as their ImageDescription text; every file
// names lensrt as its Software where the format has the field.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/preview_values.h"

namespace lensrt {

enum class PluginOutput { Tiff, Jpeg2000, WebP, Dpx };

// The format `file`'s extension asks for (any case), or nullopt.
std::optional<PluginOutput> pluginOutputFor(const std::filesystem::path& file);

// "TIFF", "JPEG 2000", "WebP", "DPX".
const char* pluginOutputLabel(PluginOutput format);

// Writes `image`'s channels `rgb` (three indices) to `temporary`, the file
// that will be renamed to `file` (which names it in errors). Throws
// InputError(file, reason), also when the plugin cannot be loaded.
// `display`: the previews' OpenColorIO display transform (not for DPX).
void writeWithPlugin(const std::filesystem::path& file, const std::filesystem::path& temporary,
                     PluginOutput format, const Image& image, const std::vector<int>& rgb,
                     const ImageMetadata& metadata, const std::optional<DisplayTransform>& display);

}  // namespace lensrt
