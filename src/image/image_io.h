// Reading and writing images: EXR through OpenEXR (exr_io.h), PNG, JPEG,
// HDR and the rest of stb_image's formats through stb (stb_io.h), and TIFF,
// DPX, JPEG 2000, WebP and what else OpenImageIO reads through lensrt's
// OpenImageIO plugin, loaded only for them (plugin_input.h, plugin_output.h).
//
// Design notes: docs/design/image-io.md.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "image/image.h"
#include "image/preview_values.h"

namespace lensrt {

struct ImageWriteOptions {
  // EXR only: store 16-bit half floats instead of 32-bit floats. Halves the
  // file size; values keep ~3 significant digits and saturate at 65504.
  bool halfFloat = false;
  // Previews only (.png, .jpg, .tif, .jp2, .webp): OpenColorIO's display
  // transform instead of the sRGB curve (preview_values.h).
  std::optional<DisplayTransform> display;
};

// Throws InputError(file, reason) with a one-line reason on any failure.
void writeImage(const std::filesystem::path& file, const Image& image, const ImageMetadata& metadata,
                const ImageWriteOptions& options = {});

// The most values (width x height x channels) a file may hold: 16 GiB of
// floats, so a corrupt header cannot ask for more memory than any machine has.
constexpr std::size_t kMaxImageValues = std::size_t(1) << 32;

// Reads an EXR (the first part), PNG, JPEG, Radiance .hdr, BMP, TGA, PSD,
// GIF, PIC or PNM file, recognised by its content, all channels as float with
// the file's channel names (R,G,B,A, or Y for grey); WebP, TIFF, JPEG 2000 and
// DPX files (by content) and the other formats OpenImageIO reads (by
// extension) through the plugin. 8-, 10- and 16-bit formats give their
// stored values scaled to [0,1] (no sRGB decoding). EXR files may list
// channels in a different order than they were written in: look channels up
// by name. When `metadata` is given it receives the EXR header's attributes
// as strings (empty for the other formats).
// Throws InputError(file, reason) when the file cannot be read.
Image readImage(const std::filesystem::path& file, ImageMetadata* metadata = nullptr);

// Throws InputError(file, "reading TIFF images needs lensrt's OpenImageIO
// plugin: ...") when `file`'s content is of a format read through the plugin
// and it cannot be loaded: a command checks this before it loads a scene.
void checkImageReader(const std::filesystem::path& file);

// readImage's image as linear light (an environment map): float files as
// they are; integer files decoded from the sRGB curve, or from Cineon log
// when the file says so (log DPX), alpha channels left alone.
Image readLinearImage(const std::filesystem::path& file);

// The same from bytes in memory (`name` labels errors): the fuzz target's
// entry point, with a smaller `maxValues` there. Formats are recognised by
// content alone.
Image decodeImage(std::string_view bytes, const std::string& name, ImageMetadata* metadata = nullptr,
                  std::size_t maxValues = kMaxImageValues);

// True when writeImage accepts the file's extension: .exr, .png, .jpg, .jpeg,
// .tif, .tiff, .dpx, .jp2, .j2k, .webp (any case). Lets commands reject a bad
// output name before rendering.
bool isWritableImageExtension(const std::filesystem::path& file);

// True for the extensions of the formats readImage reads (any case): .exr,
// .hdr, .png, .jpg, .jpeg, and the plugin's (.tif, .webp, .jp2, .dpx, ...).
bool isReadableImageExtension(const std::filesystem::path& file);

// Throws UsageError("--ocio-display", ...) unless `file` is a preview whose
// display transform can be made (the plugin loads, the config has the
// display and view): a command checks this before it renders.
void checkDisplayTransform(const std::filesystem::path& file, const DisplayTransform& display);

// Throws InputError(file, "writing TIFF files needs lensrt's OpenImageIO
// plugin: ...") when `file`'s format is written through the plugin and it
// cannot be loaded: a command checks this before it renders.
void checkImageWriter(const std::filesystem::path& file);

// Writes `file` as writeImage does, for a writer of its own format: `write`
// fills a temporary file beside it (same file system), which is then renamed
// into place, so a failed write never replaces a good file. Throws
// InputError naming `file` (and lets `write`'s exceptions through).
void writeFileThrough(const std::filesystem::path& file,
                      const std::function<void(const std::filesystem::path&)>& write);

}  // namespace lensrt
