// The image formats that lensrt decodes through its OpenImageIO plugin
// (image/oiio_plugin.h) when the bytes come from memory (glTF textures, the
// image fuzz target): WebP, TIFF, JPEG 2000 and DPX, recognised by their
// first bytes, never by a name an untrusted file chose. PNG, JPEG and the
// rest of stb_image's formats stay with stb_image, EXR with OpenEXR.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace lensrt {

struct PluginFormat {
  const char* name;   // OpenImageIO's: "webp", "tiff", "jpeg2000", "dpx"
  const char* label;  // for messages: "WebP", "TIFF", "JPEG 2000", "DPX"
};

// The format `bytes` start, or nullopt for anything else.
std::optional<PluginFormat> sniffPluginFormat(const unsigned char* bytes, std::size_t size);

struct DeclaredImageSize {
  std::uint32_t width = 0, height = 0, channels = 0;
};

// The size a WebP or JPEG 2000 header declares, read here because their
// decoders allocate the whole image as they open it, before lensrt could
// check it. nullopt for other data and for headers that cannot be read (the
// decoder then reports those). A JP2 file gives the larger of its image
// header's and its codestream's sizes.
std::optional<DeclaredImageSize> pluginFormatDeclaredSize(const unsigned char* bytes, std::size_t size);

}  // namespace lensrt
