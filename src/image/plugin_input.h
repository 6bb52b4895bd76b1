// Image files read through lensrt's OpenImageIO plugin (image/oiio_plugin.h):
// WebP, TIFF, JPEG 2000 and DPX recognised by their first bytes, and by
// their extension the other formats OpenImageIO reads and lensrt's own
// decoders do not (Cineon, DDS, HEIF/AVIF, SGI, PFM, ...).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "image/image.h"
#include "image/oiio_plugin.h"
#include "image/plugin_image_formats.h"

namespace lensrt {

// An image and how its values relate to light.
struct EncodedImage {
  Image image;
  StoredEncoding encoding = StoredEncoding::Linear;
};

// True for the extensions of formats read through the plugin (any case), so
// a file that neither lensrt's decoders nor the first bytes recognise goes
// there rather than to stb_image's error.
bool isPluginInputExtension(const std::filesystem::path& file);

// All channels as float with the file's names; integer formats give their
// codes scaled to [0,1]. Images of more than `maxValues` values are refused
// before decoding. Throw InputError, also when the plugin cannot be loaded
// (naming `label`, the format that needs it).
EncodedImage readWithPlugin(const std::filesystem::path& file, const std::string& label,
                            std::size_t maxValues);
EncodedImage decodeWithPlugin(std::string_view bytes, const PluginFormat& format, const std::string& name,
                              std::size_t maxValues);

}  // namespace lensrt
