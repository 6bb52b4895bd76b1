// The bytes of a base64 data: URI whose media type tinygltf does not decode
// itself (it knows PNG, JPEG, BMP, GIF and octet streams): image/webp and
// image/tiff textures.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace lensrt::gltf {

// The decoded bytes of "data:<type>;base64,<data>", or nullopt when `uri`
// is no base64 data: URI or its data is not base64 (padding included).
std::optional<std::string> decodeBase64DataUri(std::string_view uri);

}  // namespace lensrt::gltf
