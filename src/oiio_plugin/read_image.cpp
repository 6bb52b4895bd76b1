// Reading: a file by path (OpenImageIO finds the format) or bytes in memory
// of a format lensrt recognised, into floats, after the caller has seen the
// size the file declares.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>

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

// OpenImageIO 2.4's DPX reader fills the pixels past the end of a cut file
// with whatever its buffer held, and reports success: the header's file size
// (big-endian after "SDPX", little after "XPDS") says how long it must be.
void checkDpxLength(const unsigned char* header, std::size_t headerBytes, std::uint64_t fileBytes) {
  if (headerBytes < 20) throw Failure("the DPX header is cut short");
  std::uint32_t declared = 0;
  for (int i = 0; i < 4; ++i)
    declared |= std::uint32_t(header[16 + (header[0] == 'S' ? i : 3 - i)]) << (8 * (3 - i));
  if (fileBytes < declared) {
    std::string why = "the DPX file is cut short: its header declares ";
    why += std::to_string(declared);
    why += " bytes, it holds ";
    why += std::to_string(fileBytes);
    throw Failure(why);
  }
}

void checkDpxFile(const char* path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[20] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  std::error_code ec;
  checkDpxLength(header, std::size_t(in.gcount()), std::filesystem::file_size(path, ec));
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
    if (std::string_view(in->format_name()) == "dpx") checkDpxFile(path);
    return readOpened(*in, check, context, out);
  });
}

int lensrt_oiio_read_memory(const void* bytes, size_t size, const char* format, lensrt_oiio_size_check check,
                            void* context, lensrt_oiio_image* out) {
  return guarded([&] {
    if (std::string_view(format) == "dpx")
      checkDpxLength(static_cast<const unsigned char*>(bytes), size, size);
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
