#include "image/plugin_output.h"

#include <string>

#include "core/error.h"
#include "image/cineon.h"
#include "image/oiio_plugin.h"

namespace lensrt {
namespace {

// The metadata as lines of "key: value", the text TIFF's ImageDescription
// holds.
std::string description(const ImageMetadata& metadata) {
  std::string text;
  for (const auto& [key, value] : metadata) {
    if (!text.empty()) text += '\n';
    text += key;
    text += ": ";
    text += value;
  }
  return text;
}

}  // namespace

void writeWithPlugin(const std::filesystem::path& file, const std::filesystem::path& temporary,
                     const OutputFormat& format, const Image& image, const std::vector<int>& rgb,
                     const ImageMetadata& metadata, const std::optional<DisplayTransform>& display) {
  const OutputFormat& e = format;
  std::string purpose = "writing ";
  purpose += e.label;
  purpose += " files";
  const OiioPlugin& plugin = OiioPlugin::get(file.string(), purpose);
  std::vector<float> values;
  if (e.cineonLog) {
    const std::size_t pixelCount = std::size_t(image.width) * std::size_t(image.height);
    values.resize(pixelCount * 3);
    for (std::size_t i = 0; i < pixelCount; ++i)
      for (std::size_t c = 0; c < 3; ++c)
        values[i * 3 + c] =
            cineonEncode(image.pixels[i * image.channelCount() + std::size_t(rgb[c])]) / cineon::kMaxCode;
  } else {
    values = previewValues(file, image, rgb, display);
  }
  PluginWriteOptions options;
  options.format = e.oiioName;
  options.bits = e.bits;
  options.quality = e.quality;
  options.colorSpace = e.cineonLog ? "KodakLog" : "sRGB";
  if (e.cineonLog) options.dpxTransfer = "Printing density";
  if (const auto version = metadata.find("lensrt:version"); version != metadata.end())
    options.metadata.emplace_back("Software", std::string("lensrt ") + version->second);
  // DPX's description field holds 32 characters.
  if (!metadata.empty() && std::string(e.oiioName) == "tiff")
    options.metadata.emplace_back("ImageDescription", description(metadata));
  try {
    plugin.write(temporary, values, image.width, image.height, 3, options);
  } catch (const InputError& e) {
    throw InputError(file.string(), e.message());
  }
}

}  // namespace lensrt
