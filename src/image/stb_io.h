// PNG and JPEG previews written with stb_image_write; PNG, JPEG, Radiance
// .hdr, BMP, TGA, PSD, GIF, PIC and PNM read with stb_image (Debian's
// libstb, the decoder tinygltf already uses for the glTF textures).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

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

// 8- or 16-bit codes as glTF loaders decode textures (tinygltf's
// LoadImageData): every image expanded to RGBA, 16-bit PNGs kept at 16 bits
// (two bytes a value, in the machine's order), a Radiance .hdr file tone-
// mapped to 8 bits by stb_image. nullopt when stb_image cannot decode it.
struct StbCodes {
  int width = 0, height = 0, components = 0, bits = 8;
  std::vector<unsigned char> data;  // row-major, `components` values a pixel
};
std::optional<StbCodes> decodeStbCodes(std::string_view bytes);

// True when stb_image recognises `bytes` as one of its formats.
bool isStbImage(std::string_view bytes);

}  // namespace lensrt
