// liblensrt_oiio.so: every call lensrt makes into OpenImageIO (see oiio_api.h
// for why it is a module loaded on demand).
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "image/oiio/oiio_api.h"

namespace lensrt::oiio {
namespace {

namespace OIIO = OIIO_NAMESPACE;

// OIIO error texts can span lines; lensrt's errors promise one.
std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s.empty() ? "unknown OpenImageIO error" : s;
}

std::string write(const std::string& path, Format format, const Layout& layout, bool halfFloat,
                  int alphaChannel, const Attributes& attributes, const float* data) try {
  const char* name = format == Format::Exr ? "openexr" : format == Format::Png ? "png" : "jpeg";
  auto out = OIIO::ImageOutput::create(name);
  if (!out) return "OpenImageIO cannot write " + std::string(name) + " files";
  OIIO::ImageSpec spec;
  if (format == Format::Exr) {
    spec = OIIO::ImageSpec(layout.width, layout.height, int(layout.channels.size()),
                           halfFloat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    spec.channelnames = layout.channels;
    spec.alpha_channel = alphaChannel;
    spec.attribute("compression", "zip");
    spec.x = layout.x;
    spec.y = layout.y;
    spec.full_x = layout.fullX;
    spec.full_y = layout.fullY;
    spec.full_width = layout.fullWidth;
    spec.full_height = layout.fullHeight;
  } else {
    spec = OIIO::ImageSpec(layout.width, layout.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (format == Format::Jpeg) spec.attribute("CompressionQuality", 95);
  }
  for (const auto& [key, value] : attributes) spec.attribute(key, value);
  if (!out->open(path, spec)) return "cannot write: " + oneLine(out->geterror());
  const bool written = out->write_image(OIIO::TypeDesc::FLOAT, data);
  const std::string writeError = written ? "" : out->geterror();
  const bool closed = out->close();
  if (!written || !closed) return "cannot write: " + oneLine(written ? out->geterror() : writeError);
  return "";
} catch (const std::exception& e) {
  return "cannot write: " + oneLine(e.what());
}

std::string read(const std::string& path, Layout& layout, std::vector<float>& pixels,
                 Attributes* attributes) try {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return "cannot read image: " + oneLine(OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.depth > 1) return "volume images are not supported";
  layout.width = spec.width;
  layout.height = spec.height;
  layout.depth = spec.depth;
  layout.channels = spec.channelnames;
  layout.x = spec.x;
  layout.y = spec.y;
  layout.fullX = spec.full_x;
  layout.fullY = spec.full_y;
  layout.fullWidth = spec.full_width;
  layout.fullHeight = spec.full_height;
  pixels.assign(std::size_t(spec.width) * spec.height * spec.nchannels, 0.0f);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()))
    return "cannot read pixels: " + oneLine(in->geterror());
  if (attributes) {
    attributes->clear();
    for (const OIIO::ParamValue& p : spec.extra_attribs)
      attributes->emplace_back(p.name().string(), p.get_string());
  }
  in->close();
  return "";
} catch (const std::exception& e) {
  return "cannot read image: " + oneLine(e.what());
}

bool textSize(const std::string& text, int size, const char* font, int box[4]) {
  const OIIO::ROI roi = OIIO::ImageBufAlgo::text_size(text, size, font);
  if (!roi.defined()) return false;
  box[0] = roi.xbegin;
  box[1] = roi.xend;
  box[2] = roi.ybegin;
  box[3] = roi.yend;
  return true;
}

bool renderText(std::vector<float>& mask, int width, int height, int x, int y, const std::string& text,
                int size, const char* font) {
  OIIO::ImageBuf buffer(OIIO::ImageSpec(width, height, 1, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::zero(buffer);
  if (!OIIO::ImageBufAlgo::render_text(buffer, x, y, text, size, font, 1.0f)) return false;
  mask.assign(std::size_t(width) * height, 0.0f);
  buffer.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 1), OIIO::TypeDesc::FLOAT, mask.data());
  return true;
}

std::string colorMap(const std::vector<float>& values, int width, int height, const char* map,
                     std::vector<float>& rgb) {
  // Wraps the caller's memory: the ImageBuf does not outlive this call.
  OIIO::ImageBuf src(OIIO::ImageSpec(width, height, 1, OIIO::TypeDesc::FLOAT),
                     const_cast<float*>(values.data()));
  const OIIO::ImageBuf mapped = OIIO::ImageBufAlgo::color_map(src, 0, map);
  if (mapped.has_error()) return oneLine(mapped.geterror());
  rgb.assign(std::size_t(width) * height * 3, 0.0f);
  mapped.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, rgb.data());
  return "";
}

constexpr Api kApi{kApiVersion, write, read, textSize, renderText, colorMap};

}  // namespace
}  // namespace lensrt::oiio

extern "C" __attribute__((visibility("default"))) const lensrt::oiio::Api* lensrt_oiio_api() {
  return &lensrt::oiio::kApi;
}
