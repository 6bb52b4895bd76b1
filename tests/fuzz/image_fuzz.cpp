// libFuzzer target for the image readers (`lensrt diff`, `--env`, merge,
// resume): bytes through decodeImage, i.e. OpenEXR for EXR files, the
// OpenImageIO plugin for WebP, TIFF, JPEG 2000 and DPX (when
// LENSRT_OIIO_PLUGIN names one: else those are an InputError), and
// stb_image for PNG, JPEG, HDR and the rest. Only InputError may escape; a
// decoded image must be consistent, and a small one must survive a float EXR
// round trip bit for bit.
#include <ImfHeader.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/error.h"
#include "fuzz/fuzz_check.h"
#include "fuzz/oiio_plugin_first.h"
#include "image/image_io.h"

namespace {

// OpenEXR sizes some buffers from the header before lensrt sees it: keep
// claimed sizes within what a fuzzer's memory limit allows.
const bool kOpenExrLimits = [] {
  Imf::Header::setMaxImageSize(8192, 8192);
  Imf::Header::setMaxTileSize(1024, 1024);
  return true;
}();

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  lensrt::fuzz::loadOiioPluginFirst();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lensrt;
  (void)kOpenExrLimits;
  try {
    ImageMetadata metadata;
    const Image image = decodeImage(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.img",
                                    &metadata, std::size_t(1) << 22);
    LENSRT_FUZZ_CHECK(image.width > 0 && image.height > 0 && image.channelCount() > 0);
    LENSRT_FUZZ_CHECK(image.pixels.size() == std::size_t(image.width) * image.height * image.channelCount());
    if (image.pixels.size() > 4096) return 0;
    const std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("lensrt-fuzz-image-" + std::to_string(::getpid()) + ".exr");
    writeImage(path, image, {});
    const Image again = readImage(path);
    std::filesystem::remove(path);
    LENSRT_FUZZ_CHECK(again.width == image.width && again.height == image.height);
    LENSRT_FUZZ_CHECK(again.originX == image.originX && again.originY == image.originY);
    LENSRT_FUZZ_CHECK(again.fullWidth() == image.fullWidth() && again.fullHeight() == image.fullHeight());
    LENSRT_FUZZ_CHECK(again.channelCount() == image.channelCount());
    // EXR files keep channels by name (a grey image's Y,A reads back as A,Y).
    for (std::size_t c = 0; c < image.channelCount(); ++c) {
      const int k = again.channelIndex(image.channels[c]);
      LENSRT_FUZZ_CHECK(k >= 0);
      for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
        LENSRT_FUZZ_CHECK(std::memcmp(&again.pixels[p * again.channelCount() + k],
                                      &image.pixels[p * image.channelCount() + c], sizeof(float)) == 0);
    }
  } catch (const InputError&) {
  }
  return 0;
}
