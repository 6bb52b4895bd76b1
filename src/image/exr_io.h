// OpenEXR files through the OpenEXR library itself. (OpenImageIO did this
// before; its ~260 shared libraries cost every lensrt process 0.3 s and
// 135 MB before any work.)
//
// Written: the channels by name as float or half, ZIP compression, the data
// window (a crop or tile) inside the display window (the whole frame), the
// metadata as string attributes under their keys, and capDate (the time of
// writing, "YYYY:MM:DD HH:MM:SS", as OpenImageIO wrote it).
// Read: the first part of any scanline or tiled file, every channel as float.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "image/image.h"

namespace lensrt {

// The file's bytes; throws InputError(name, reason) when OpenEXR refuses.
std::string encodeExr(const std::string& name, const Image& image, const ImageMetadata& metadata,
                      bool halfFloat);

// True when `head` starts with OpenEXR's magic number.
bool looksLikeExr(std::string_view head);

// Channels come in OpenImageIO's order (what readers of lensrt's EXRs saw
// before): by layer ("" first, then "albedo.", "depth.", ...), within a layer
// R, G, B, A, then X, Y, Z, then the rest by name. `metadata` receives the
// string attributes under their names, capDate as "DateTime", the
// compression as "compression" ("zip", "piz", ...) and numeric attributes as
// text. Images of more than `maxValues` floats are refused before decoding.
Image readExrFile(const std::filesystem::path& file, ImageMetadata* metadata, std::size_t maxValues);
Image decodeExr(std::string_view bytes, const std::string& name, ImageMetadata* metadata,
                std::size_t maxValues);

}  // namespace lensrt
