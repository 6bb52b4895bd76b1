// PNG and JPEG previews written with stb_image_write; PNG, JPEG, Radiance
// .hdr, BMP, TGA, PSD, GIF, PIC and PNM read with stb_image (Debian's
// libstb, the decoder tinygltf already uses for the glTF textures).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "image/image.h"

namespace lensrt {

enum class PreviewFormat { Png, Jpeg };

// `rgb` holds width*height*3 8-bit sRGB codes, row 0 at the top. PNG files
// carry `metadata` as text chunks (tEXt, or iTXt for UTF-8 values); JPEG
// files are quality 95 without chroma subsampling and carry no metadata.
// Throws InputError(name, reason).
std::string encodePreview(const std::string& name, PreviewFormat format, int width, int height,
                          const std::string& rgb, const ImageMetadata& metadata);

// Channels R,G,B(,A), or Y(,A) for grey images. 8- and 16-bit files give
// their stored codes scaled to [0,1] (no sRGB decoding; alpha unassociated,
// as stored); .hdr files their linear values. Images of more than
// `maxValues` values are refused before decoding. Throws InputError.
Image decodeStbImage(std::string_view bytes, const std::string& name, std::size_t maxValues);

// True when stb_image recognises `bytes` as one of its formats.
bool isStbImage(std::string_view bytes);

}  // namespace lensrt
