// Every image format lensrt writes (-o, --heatmap, Python's write): its
// extensions, what a file holds, and which encoder writes it. Adding a
// format is a row here (and its encoder, when the plugin does not have it);
// the commands' help and messages list the formats from these rows.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lensrt {

enum class ImageEncoder {
  Exr,     // OpenEXR, every channel (image/exr_io.h)
  Png,     // stb_image_write (image/stb_io.h)
  Jpeg,    // stb_image_write
  Plugin,  // OpenImageIO through lensrt's plugin (image/plugin_output.h)
};

// What a file is for, as -o's messages group the formats.
enum class ImageRole { FullResult, Preview, Log };

struct OutputFormat {
  std::vector<std::string> extensions;  // lower case; the first is the one messages name
  const char* label;                    // "TIFF", for messages
  const char* holds;                    // "16-bit sRGB", for help
  ImageEncoder encoder;
  ImageRole role;
  // Through the plugin: OpenImageIO's format name, bits per value, quality
  // (0: lossless) and whether values are Cineon log (image/cineon.h).
  const char* oiioName = "";
  int bits = 8;
  int quality = 0;
  bool cineonLog = false;
};

const std::vector<OutputFormat>& outputFormats();

// The format `file`'s extension names (any case), or null.
const OutputFormat* outputFormatFor(const std::filesystem::path& file);

// ".exr, .png, .jpg, .tif, .jp2, .webp or .dpx" (the formats of `role` only,
// when given: ".png, .jpg, .tif, .jp2, .webp").
std::string outputExtensionList(const char* lastJoin = " or ");
std::string outputExtensionList(ImageRole role, const char* lastJoin = " or ");

// ".exr (linear float, all channels and metadata), .png/.jpg (8-bit sRGB
// preview), ... or .dpx (10-bit Cineon log)": -o's help.
std::string outputFormatHelp();

// "use .exr for the full result; .png, .jpg, .tif, .jp2 or .webp for a
// preview, .dpx for 10-bit log": what an unknown extension's message suggests.
std::string outputFormatAdvice();

}  // namespace lensrt
