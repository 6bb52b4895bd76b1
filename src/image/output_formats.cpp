#include "image/output_formats.h"

#include <algorithm>
#include <cctype>

#include "core/ascii_lower.h"

namespace lensrt {

const std::vector<OutputFormat>& outputFormats() {
  static const std::vector<OutputFormat> formats{
      {{".exr"},
       "OpenEXR",
       "linear float, all channels and metadata",
       ImageEncoder::Exr,
       ImageRole::FullResult},
      {{".png"}, "PNG", "8-bit sRGB preview", ImageEncoder::Png, ImageRole::Preview},
      {{".jpg", ".jpeg"}, "JPEG", "8-bit sRGB preview", ImageEncoder::Jpeg, ImageRole::Preview},
      // ZIP-compressed; the metadata as its ImageDescription.
      {{".tif", ".tiff"}, "TIFF", "16-bit sRGB", ImageEncoder::Plugin, ImageRole::Preview, "tiff", 16},
      // Lossless; at least 32x32 pixels.
      {{".jp2", ".j2k"},
       "JPEG 2000",
       "16-bit sRGB",
       ImageEncoder::Plugin,
       ImageRole::Preview,
       "jpeg2000",
       16},
      // Lossy at quality 95 with chroma at half resolution, as WebP's lossy
      // mode has it (OpenImageIO 2.4's lossless mode halves the chroma too).
      {{".webp"}, "WebP", "8-bit sRGB", ImageEncoder::Plugin, ImageRole::Preview, "webp", 8, 95},
      // Scene-linear 1.0 at code 685, highlights kept up to 13.5: for grading.
      {{".dpx"}, "DPX", "10-bit Cineon log", ImageEncoder::Plugin, ImageRole::Log, "dpx", 10, 0, true},
  };
  return formats;
}

const OutputFormat* outputFormatFor(const std::filesystem::path& file) {
  const std::string ext = lowerExtension(file);
  for (const OutputFormat& f : outputFormats())
    if (std::find(f.extensions.begin(), f.extensions.end(), ext) != f.extensions.end()) return &f;
  return nullptr;
}

namespace {

std::string joined(const std::vector<std::string>& items, const char* lastJoin) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += i + 1 == items.size() ? lastJoin : ", ";
    text += items[i];
  }
  return text;
}

std::string listOf(bool (*keep)(const OutputFormat&, ImageRole), ImageRole role, const char* lastJoin) {
  std::vector<std::string> names;
  for (const OutputFormat& f : outputFormats())
    if (keep(f, role)) names.push_back(f.extensions.front());
  return joined(names, lastJoin);
}

}  // namespace

std::string outputExtensionList(const char* lastJoin) {
  return listOf([](const OutputFormat&, ImageRole) { return true; }, ImageRole::Preview, lastJoin);
}

std::string outputExtensionList(ImageRole role, const char* lastJoin) {
  return listOf([](const OutputFormat& f, ImageRole r) { return f.role == r; }, role, lastJoin);
}

std::string outputFormatHelp() {
  // Neighbours that hold the same are named together: ".png/.jpg (8-bit sRGB preview)".
  std::vector<std::string> parts;
  const std::vector<OutputFormat>& formats = outputFormats();
  for (std::size_t i = 0; i < formats.size();) {
    std::string names = formats[i].extensions.front();
    std::size_t j = i + 1;
    for (; j < formats.size() && std::string(formats[j].holds) == formats[i].holds; ++j)
      names += "/" + formats[j].extensions.front();
    parts.push_back(names + " (" + formats[i].holds + ")");
    i = j;
  }
  return joined(parts, " or ");
}

std::string outputFormatAdvice() {
  return "use " + outputExtensionList(ImageRole::FullResult) + " for the full result; " +
         outputExtensionList(ImageRole::Preview) + " for a preview, " + outputExtensionList(ImageRole::Log) +
         " for 10-bit log";
}

}  // namespace lensrt
