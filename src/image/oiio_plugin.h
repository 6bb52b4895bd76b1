// lensrt's OpenImageIO plugin, lensrt_oiio.so (src/oiio_plugin/), loaded
// with dlopen the first time a file's format needs it and kept until exit:
// the formats lensrt's own decoders do not cover (TIFF, DPX, JPEG 2000,
// WebP and the rest of what OpenImageIO reads) and OpenColorIO's display
// transforms. Processes that never need it never pay OpenImageIO's start-up
// (0.3 s, 135 MB).
//
// It is looked for, in order: the file $LENSRT_OIIO_PLUGIN names (then
// nowhere else); beside the running executable; in ../lib/lensrt from it;
// beside the shared object holding this code (the Python module).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/shared_library.h"
#include "image/oiio_plugin_abi.h"

namespace lensrt {

// How an image file's values relate to light (lensrt_oiio_image.encoding).
enum class StoredEncoding { Linear, Srgb, Cineon };

struct PluginImage {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;  // the file's names: R,G,B,A, Y, ...
  std::vector<float> pixels;          // interleaved, row 0 at the top
  StoredEncoding encoding = StoredEncoding::Linear;
};

struct PluginWriteOptions {
  std::string format;  // OpenImageIO's name: "tiff", "dpx", "jpeg2000", "webp"
  int bits = 8;
  int quality = 0;  // lossy quality 1..100; 0: lossless
  std::string colorSpace;
  std::string dpxTransfer;
  std::vector<std::pair<std::string, std::string>> metadata;
};

class OiioPlugin {
 public:
  // The plugin, loaded on the first call in the process (thread-safe).
  // Throws InputError(file, "<purpose> needs lensrt's OpenImageIO plugin:
  // <why not>"): `purpose` names what needs it, e.g. "writing TIFF files".
  // A failed load is remembered, not retried.
  static const OiioPlugin& get(const std::string& file, const std::string& purpose);
  // The same without throwing: nullptr, and why in `problem`, when it cannot
  // be loaded (for callers that have another way, such as a fallback image).
  static const OiioPlugin* find(std::string& problem);

  // Throws before decoding with the size the file declares (width, height,
  // channels) to refuse it.
  using SizeCheck = std::function<void(int width, int height, int channels)>;

  // Throw InputError(name, "cannot read image: <OpenImageIO's reason>").
  PluginImage readFile(const std::filesystem::path& file, const SizeCheck& check) const;
  PluginImage readMemory(std::string_view bytes, const char* format, const std::string& name,
                         const SizeCheck& check) const;

  // Writes `file` (a temporary one: see image_io.h's writeFileThrough).
  // Throws InputError(file, "cannot write: <reason>").
  void write(const std::filesystem::path& file, const std::vector<float>& pixels, int width, int height,
             int channels, const PluginWriteOptions& options) const;

  // OpenColorIO's display transform, in place on RGB triples. Throws
  // UsageError(option, <reason and the displays there are>).
  void displayTransform(const std::string& option, std::vector<float>& rgb, const std::string& display,
                        const std::string& view) const;

  // "OpenImageIO 2.4.7 (OpenColorIO 2.1.2)".
  std::string libraryVersion() const;
  const std::filesystem::path& file() const { return library_.file(); }

 private:
  explicit OiioPlugin(SharedLibrary library);
  friend struct OiioPluginLoader;

  template <class F>
  F function(const char* name) const;
  std::string lastError() const;
  PluginImage take(lensrt_oiio_image& image) const;

  SharedLibrary library_;
  decltype(&lensrt_oiio_library_version) libraryVersion_;
  decltype(&lensrt_oiio_read_file) readFile_;
  decltype(&lensrt_oiio_read_memory) readMemory_;
  decltype(&lensrt_oiio_write) write_;
  decltype(&lensrt_oiio_display_transform) displayTransform_;
  decltype(&lensrt_oiio_displays) displays_;
  decltype(&lensrt_oiio_free) free_;
  decltype(&lensrt_oiio_last_error) lastError_;
};

}  // namespace lensrt
