// Reading: a file by path (OpenImageIO finds the format) or bytes in memory
// of a format lensrt recognised, into floats, after the caller has seen the
// size the file declares.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "core/oiio_plugin_abi.h"
#include "oiio_plugin/plugin_call.h"

namespace lensrt::oiio {
namespace {

// What OpenImageIO says about the values, else what is usual for the type:
// floats are linear light, integers sRGB codes.
int encodingOf(const OIIO::ImageSpec& spec) {
  using OIIO::Strutil::iequals;
  const std::string transfer = spec.get_string_attribute("dpx:Transfer");
  const std::string space = spec.get_string_attribute("oiio:ColorSpace");
  if (iequals(transfer, "Printing density") || iequals(transfer, "Logarithmic") ||
      iequals(space, "KodakLog") || iequals(space, "Cineon"))
    return LENSRT_OIIO_CINEON;
  if (iequals(space, "linear") || iequals(space, "scene_linear") || iequals(space, "lin_rec709") ||
      iequals(transfer, "Linear"))
    return LENSRT_OIIO_LINEAR;
  if (!space.empty()) return LENSRT_OIIO_SRGB;  // sRGB, Rec709, GammaX.Y: display curves near enough
  return spec.format.is_floating_point() ? LENSRT_OIIO_LINEAR : LENSRT_OIIO_SRGB;
}

char* copyOf(const std::string& text) {
  char* out = static_cast<char*>(std::malloc(text.size() + 1));
  if (!out) throw std::bad_alloc();
  std::memcpy(out, text.c_str(), text.size() + 1);
  return out;
}

struct FreeBuffer {
  void operator()(void* p) const { std::free(p); }
};

int readOpened(OIIO::ImageInput& in, lensrt_oiio_size_check check, void* context, lensrt_oiio_image* out) {
  const OIIO::ImageSpec spec = in.spec();
  if (spec.deep) throw Failure("deep images are not supported");
  if (spec.depth > 1) throw Failure("volume images are not supported");
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) throw Failure("the image is empty");
  if (check && !check(context, spec.width, spec.height, spec.nchannels)) {
    setLastError("refused");
    return LENSRT_OIIO_REFUSED;
  }
  const std::size_t count = std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels);
  std::unique_ptr<float, FreeBuffer> pixels(static_cast<float*>(std::malloc(count * sizeof(float))));
  if (!pixels) throw std::bad_alloc();
  if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.get()))
    throw Failure(oneLine(in.geterror(), "the pixels cannot be decoded"));
  std::string names;
  for (int c = 0; c < spec.nchannels; ++c) {
    if (c > 0) names += ',';
    names += c < int(spec.channelnames.size()) ? spec.channelnames[std::size_t(c)] : std::string();
  }
  std::unique_ptr<char, FreeBuffer> channelNames(copyOf(names));
  *out = lensrt_oiio_image{spec.width,       spec.height,      spec.nchannels,
                           encodingOf(spec), pixels.release(), channelNames.release()};
  return LENSRT_OIIO_OK;
}

// Alpha as stored: OpenImageIO would premultiply unassociated alpha.
OIIO::ImageSpec readConfig() {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  return config;
}

}  // namespace
}  // namespace lensrt::oiio

using namespace lensrt::oiio;

extern "C" {

int lensrt_oiio_read_file(const char* path, lensrt_oiio_size_check check, void* context,
                          lensrt_oiio_image* out) {
  return guarded([&] {
    const OIIO::ImageSpec config = readConfig();
    const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) throw Failure(oneLine(OIIO::geterror(), "OpenImageIO does not recognise the file"));
    return readOpened(*in, check, context, out);
  });
}

int lensrt_oiio_read_memory(const void* bytes, size_t size, const char* format, lensrt_oiio_size_check check,
                            void* context, lensrt_oiio_image* out) {
  return guarded([&] {
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::create(format);
    if (!in) throw Failure(oneLine(OIIO::geterror(), "OpenImageIO has no reader for it"));
    if (!in->supports("ioproxy"))
      throw Failure("OpenImageIO's reader of this format cannot read from memory");
    OIIO::Filesystem::IOMemReader reader(const_cast<void*>(bytes), size);
    OIIO::ImageSpec config = readConfig();
    void* proxy = &reader;
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    // A fixed name: with the proxy, OpenImageIO opens no file by it.
    const std::string name = std::string("memory.") + format;
    OIIO::ImageSpec spec;
    if (!in->open(name, spec, config)) throw Failure(oneLine(in->geterror(), "not a valid image"));
    return readOpened(*in, check, context, out);
  });
}

}  // extern "C"
