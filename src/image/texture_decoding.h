// A glTF texture image's encoded bytes to linear float RGBA texels: PNG,
// JPEG and the rest of stb_image's formats through tinygltf's decoder, and
// WebP (EXT_texture_webp), TIFF, JPEG 2000 and DPX, recognised by their first
// bytes, through the OpenImageIO plugin (image/oiio_plugin.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "image/texture.h"

namespace lensrt {

// Width and height a PNG, JPEG, WebP or JPEG 2000 header declares, read
// before a decoder allocates for them; nullopt for other formats and broken
// headers (the decoder then reports those).
std::optional<std::pair<std::uint32_t, std::uint32_t>> declaredTextureSize(const unsigned char* bytes,
                                                                           std::size_t size);

// Why an image gave no texture: `why` completes "texture image 'NAME' ...";
// `pluginProblem` is set when the format needs the OpenImageIO plugin and it
// cannot be loaded (why not).
struct TextureDecodeFailure {
  std::string why;
  std::string pluginLabel;  // the format that needs the plugin: "WebP"
  std::string pluginProblem;
};

// Called with the decoded (or, through the plugin, declared) size before
// the texels are made; throws to refuse it.
using TextureSizeCheck = std::function<void(std::uint32_t width, std::uint32_t height)>;

// Colour channels decoded from sRGB when `srgb` (alpha never is). The name
// and sampler are left to the caller.
std::variant<Texture, TextureDecodeFailure> decodeTextureImage(const unsigned char* bytes, std::size_t size,
                                                               bool srgb, const TextureSizeCheck& checkSize);

}  // namespace lensrt
