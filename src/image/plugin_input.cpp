#include "image/plugin_input.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <set>
#include <string>
#include <vector>

#include "core/ascii_lower.h"
#include "core/error.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;

// Still-image formats OpenImageIO reads that lensrt's decoders do not, or
// not in every variant (stb_image reads common BMP, TGA, PSD, GIF, PNM and
// PIC files; the plugin gets those it cannot). Not video, camera raw files
// or volumes.
constexpr std::array<const char*, 31> kExtensions = {
    ".tif",  ".tiff", ".tx",  ".webp", ".jp2", ".j2k", ".j2c",  ".dpx", ".cin", ".dds",  ".heic",
    ".heif", ".avif", ".ico", ".iff",  ".sgi", ".rgb", ".rgba", ".bw",  ".rla", ".fits", ".pfm",
    ".ppm",  ".pgm",  ".pbm", ".pnm",  ".bmp", ".dib", ".tga",  ".psd", ".gif"};

// The check of the size a file declares, before the plugin decodes it.
OiioPlugin::SizeCheck sizeCheck(const std::string& name, std::size_t maxValues) {
  return [name, maxValues](int width, int height, int channels) {
    if (double(width) * double(height) * double(channels) > double(maxValues))
      throw InputError(name, std::string("the image is ") + std::to_string(width) + "x" +
                                 std::to_string(height) + " with " + std::to_string(channels) +
                                 " channels, more than " + std::to_string(maxValues) + " values");
  };
}

// Names as the file gives them; where a file has none (or repeats one),
// lensrt's usual Y / Y,A / R,G,B / R,G,B,A, else C0, C1, ...
std::vector<std::string> channelNames(const std::vector<std::string>& given) {
  const std::set<std::string> distinct(given.begin(), given.end());
  const bool usable =
      distinct.size() == given.size() &&
      std::none_of(given.begin(), given.end(), [](const std::string& n) { return n.empty(); });
  if (usable) return given;
  static const std::vector<std::string> kUsual[4] = {
      {"Y"}, {"Y", "A"}, {"R", "G", "B"}, {"R", "G", "B", "A"}};
  if (given.size() >= 1 && given.size() <= 4) return kUsual[given.size() - 1];
  std::vector<std::string> names;
  for (std::size_t c = 0; c < given.size(); ++c) {
    std::string name = "C";  // appended: GCC 12 bug 105329
    name += std::to_string(c);
    names.push_back(std::move(name));
  }
  return names;
}

EncodedImage toImage(PluginImage&& read) {
  EncodedImage out;
  out.image.width = read.width;
  out.image.height = read.height;
  out.image.channels = channelNames(read.channels);
  out.image.pixels = std::move(read.pixels);
  out.encoding = read.encoding;
  return out;
}

std::string purposeOf(const std::string& label) {
  std::string purpose = "reading ";
  purpose += label;
  purpose += " images";
  return purpose;
}

}  // namespace

bool isPluginInputExtension(const fs::path& file) {
  const std::string ext = lowerExtension(file);
  return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

EncodedImage readWithPlugin(const fs::path& file, const std::string& label, std::size_t maxValues) {
  const OiioPlugin& plugin = OiioPlugin::get(file.string(), purposeOf(label));
  return toImage(plugin.readFile(file, sizeCheck(file.string(), maxValues)));
}

EncodedImage decodeWithPlugin(std::string_view bytes, const PluginFormat& format, const std::string& name,
                              std::size_t maxValues) {
  const OiioPlugin& plugin = OiioPlugin::get(name, purposeOf(format.label));
  // WebP and JPEG 2000 decoders allocate the whole image as they open it.
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  if (const std::optional<DeclaredImageSize> declared = pluginFormatDeclaredSize(data, bytes.size()))
    sizeCheck(name, maxValues)(int(std::min<std::uint32_t>(declared->width, 1u << 30)),
                               int(std::min<std::uint32_t>(declared->height, 1u << 30)),
                               int(std::min<std::uint32_t>(declared->channels, 1u << 30)));
  return toImage(plugin.readMemory(bytes, format.name, name, sizeCheck(name, maxValues)));
}

}  // namespace lensrt
