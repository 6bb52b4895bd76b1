#include "image/texture_decoding.h"

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "image/oiio_plugin.h"
#include "image/plugin_image_formats.h"
#include "image/png_allocation.h"
#include "image/stb_io.h"

namespace lensrt {
namespace {

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// Decoded pixels: 8- or 16-bit codes as glTF loaders decode them
// (image/stb_io.h's decodeStbCodes), or floats (codes scaled to [0,1]) from the plugin.
struct Pixels {
  int width = 0, height = 0, components = 0, bits = 8;  // bits 32: `floats`
  std::vector<unsigned char> data;
  std::vector<float> floats;
};

Texture toTexture(const Pixels& p, bool srgb) {
  // 8-bit colour goes through a table: decoding is per texel, pow is slow.
  std::array<float, 256> table{};
  for (int i = 0; i < 256; ++i) table[i] = srgb ? srgbToLinear(i / 255.0f) : i / 255.0f;
  const auto channel = [&](std::size_t at, bool colour) {
    if (p.bits == 32) return colour && srgb ? srgbToLinear(p.floats[at]) : p.floats[at];
    if (p.bits == 16) {
      const float v = (p.data[2 * at] | (p.data[2 * at + 1] << 8)) / 65535.0f;
      return colour && srgb ? srgbToLinear(v) : v;
    }
    return colour ? table[p.data[at]] : p.data[at] / 255.0f;
  };
  Texture t;
  t.width = p.width;
  t.height = p.height;
  const std::size_t n = static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height);
  const auto c = static_cast<std::size_t>(p.components);
  t.texels.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t at = i * c;
    Vec4f& out = t.texels[i];
    if (c >= 3) {
      out = {channel(at, true), channel(at + 1, true), channel(at + 2, true),
             c == 4 ? channel(at + 3, false) : 1};
    } else {  // grey, grey + alpha
      const float g = channel(at, true);
      out = {g, g, g, c == 2 ? channel(at + 1, false) : 1};
    }
  }
  return t;
}

// More channels than a texture holds (a JPEG 2000 codestream may declare
// thousands): refused before decoding.
struct TooManyChannels {
  int channels;
};

std::variant<Texture, TextureDecodeFailure> decodeThroughPlugin(const unsigned char* bytes, std::size_t size,
                                                                const PluginFormat& format, bool srgb,
                                                                const TextureSizeCheck& checkSize) {
  std::string problem;
  const OiioPlugin* plugin = OiioPlugin::find(problem);
  if (!plugin) return TextureDecodeFailure{"", format.label, problem};
  bool checking = false;  // an error from the size check is the caller's, not a decoding failure
  PluginImage image;
  try {
    image = plugin->readMemory(std::string_view(reinterpret_cast<const char*>(bytes), size), format.name,
                               "texture", [&](int width, int height, int channels) {
                                 if (channels > 4) throw TooManyChannels{channels};
                                 checking = true;
                                 checkSize(std::uint32_t(width), std::uint32_t(height));
                                 checking = false;
                               });
  } catch (const TooManyChannels& t) {
    return TextureDecodeFailure{
        std::string("has ") + std::to_string(t.channels) + " channels (a texture has at most 4)", "", ""};
  } catch (const InputError&) {
    if (checking) throw;
    return TextureDecodeFailure{"could not be decoded", "", ""};
  }
  Pixels p{image.width, image.height, int(image.channels.size()), 32, {}, std::move(image.pixels)};
  return toTexture(p, srgb);
}

}  // namespace

std::optional<std::pair<std::uint32_t, std::uint32_t>> declaredTextureSize(const unsigned char* b,
                                                                           std::size_t n) {
  if (const auto png = pngDeclaredSize(b, n)) return png;
  if (const std::optional<DeclaredImageSize> s = pluginFormatDeclaredSize(b, n))
    return std::pair{s->width, s->height};
  if (n < 4 || b[0] != 0xFF || b[1] != 0xD8) return std::nullopt;
  // JPEG: walk the segments to the first start-of-frame marker.
  std::size_t at = 2;
  while (at + 9 < n) {
    if (b[at] != 0xFF) return std::nullopt;
    const unsigned char marker = b[at + 1];
    const std::size_t length = (std::size_t{b[at + 2]} << 8) | b[at + 3];
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof)
      return std::pair{std::uint32_t((b[at + 7] << 8) | b[at + 8]),
                       std::uint32_t((b[at + 5] << 8) | b[at + 6])};
    if (length < 2) return std::nullopt;
    at += 2 + length;
  }
  return std::nullopt;
}

std::variant<Texture, TextureDecodeFailure> decodeTextureImage(const unsigned char* bytes, std::size_t size,
                                                               bool srgb, const TextureSizeCheck& checkSize) {
  if (const std::optional<PluginFormat> format = sniffPluginFormat(bytes, size))
    return decodeThroughPlugin(bytes, size, *format, srgb, checkSize);
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return TextureDecodeFailure{"could not be decoded", "", ""};
  std::optional<StbCodes> decoded =
      decodeStbCodes(std::string_view(reinterpret_cast<const char*>(bytes), size));
  if (!decoded) return TextureDecodeFailure{"could not be decoded", "", ""};
  Pixels p{decoded->width, decoded->height, decoded->components, decoded->bits, std::move(decoded->data), {}};
  const std::size_t bytesPerChannel = p.bits == 16 ? 2 : 1;
  if (p.width <= 0 || p.height <= 0 || p.components < 1 || p.components > 4 ||
      (p.bits != 8 && p.bits != 16) ||
      p.data.size() < static_cast<std::size_t>(p.width) * static_cast<std::size_t>(p.height) *
                          static_cast<std::size_t>(p.components) * bytesPerChannel)
    return TextureDecodeFailure{"decoded to an unexpected pixel format", "", ""};
  checkSize(std::uint32_t(p.width), std::uint32_t(p.height));
  return toTexture(p, srgb);
}

}  // namespace lensrt
