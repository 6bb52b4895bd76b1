// Writing: floats into a file of the format asked for, checked by opening
// it again.
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>

#include "image/oiio_plugin_abi.h"
#include "oiio_plugin/plugin_call.h"

namespace lensrt::oiio {
namespace {

OIIO::ImageSpec specFor(int width, int height, int channels, const lensrt_oiio_write_options& o) {
  const std::string format = o.format;
  OIIO::ImageSpec spec(width, height, channels, o.bits <= 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
  if (o.bits != 8 && o.bits != 16) spec.attribute("oiio:BitsPerSample", o.bits);
  if (format == "webp") {
    std::string compression = "lossless";
    if (o.quality > 0) {
      compression = "webp:";
      compression += std::to_string(o.quality);
    }
    spec.attribute("compression", compression);
  } else if (format == "tiff") {
    spec.attribute("compression", "zip");
  }
  if (o.color_space && *o.color_space) spec.attribute("oiio:ColorSpace", o.color_space);
  if (o.dpx_transfer && *o.dpx_transfer) {
    spec.attribute("dpx:Transfer", o.dpx_transfer);
    spec.attribute("dpx:Colorimetric", o.dpx_transfer);
  }
  for (const char* const* m = o.metadata; m && m[0] && m[1]; m += 2) spec.attribute(m[0], m[1]);
  return spec;
}

// Whether the file is an image of that size: OpenImageIO 2.4 reports some
// failures only in its error text (OpenJPEG's), and some errors that are
// none (libtiff 4.5's empty Exif directory), so its word alone cannot say.
bool opensAs(const std::string& path, const std::string& format, int width, int height) {
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(format);
  if (!in) return false;
  OIIO::ImageSpec spec;
  const bool ok = in->open(path, spec) && spec.width == width && spec.height == height;
  in->geterror();  // a failed check leaves nothing behind
  return ok;
}

int write(const char* path, const float* pixels, int width, int height, int channels,
          const lensrt_oiio_write_options& o) {
  const std::string format = o.format ? o.format : "";
  // OpenJPEG's default 6 resolution levels halve the image 5 times.
  if (format == "jpeg2000" && (width < 32 || height < 32))
    throw Failure("a JPEG 2000 image needs at least 32x32 pixels");
  std::unique_ptr<OIIO::ImageOutput> writer = OIIO::ImageOutput::create(format);
  if (!writer) throw Failure(oneLine(OIIO::geterror(), "OpenImageIO has no writer for this format"));
  const bool written = writer->open(path, specFor(width, height, channels, o)) &&
                       writer->write_image(OIIO::TypeDesc::FLOAT, pixels);
  const bool closed = writer->close();
  const std::string errors = writer->geterror();
  if (!written || !closed || !opensAs(path, format, width, height))
    throw Failure(oneLine(errors, "OpenImageIO could not write the image"));
  return LENSRT_OIIO_OK;
}

}  // namespace
}  // namespace lensrt::oiio

extern "C" int lensrt_oiio_write(const char* path, const float* pixels, int width, int height, int channels,
                                 const lensrt_oiio_write_options* options) {
  return lensrt::oiio::guarded(
      [&] { return lensrt::oiio::write(path, pixels, width, height, channels, *options); });
}
