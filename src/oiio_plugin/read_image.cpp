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
#include <utility>

#include "image/oiio_plugin_abi.h"
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

// OpenImageIO 2.4's DPX reader trusts the header: it allocates the user data
// size it declares (4 GiB from a 4-byte change, then an assertion aborts the
// process: found by fuzz_image) and reads a cut file without complaint, the
// missing pixels uninitialised. So the header's sizes (big-endian after
// "SDPX", little-endian after "XPDS") must fit the file; all ones is DPX's
// "undefined".
constexpr std::size_t kDpxHeaderBytes = 36;
constexpr std::uint32_t kDpxUndefined = 0xffffffff;

void checkDpxHeader(const unsigned char* header, std::size_t headerBytes, std::uint64_t fileBytes) {
  if (headerBytes < kDpxHeaderBytes) throw Failure("the DPX header is cut short");
  const auto field = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i)
      v |= std::uint32_t(header[at + (header[0] == 'S' ? i : 3 - i)]) << (8 * (3 - i));
    return v;
  };
  if (const std::uint32_t declared = field(16); fileBytes < declared) {
    std::string why = "the DPX file is cut short: its header declares ";
    why += std::to_string(declared);
    why += " bytes, it holds ";
    why += std::to_string(fileBytes);
    throw Failure(why);
  }
  for (const auto& [at, what] :
       {std::pair{std::size_t(4), "image data offset"}, std::pair{std::size_t(32), "user data size"}})
    if (const std::uint32_t v = field(at); v != kDpxUndefined && v > fileBytes) {
      std::string why = "the DPX header's ";
      why += what;
      why += ", ";
      why += std::to_string(v);
      why += ", is beyond the file's ";
      why += std::to_string(fileBytes);
      why += " bytes";
      throw Failure(why);
    }
}

bool isDpx(const unsigned char* bytes, std::size_t size) {
  return size >= 4 && (std::memcmp(bytes, "SDPX", 4) == 0 || std::memcmp(bytes, "XPDS", 4) == 0);
}

// A file's DPX header, checked before OpenImageIO opens it.
void checkIfDpxFile(const char* path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[kDpxHeaderBytes] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  const std::size_t got = std::size_t(in.gcount());
  if (!isDpx(header, got)) return;
  std::error_code ec;
  checkDpxHeader(header, got, std::filesystem::file_size(path, ec));
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
    checkIfDpxFile(path);
    const OIIO::ImageSpec config = readConfig();
    const std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) throw Failure(oneLine(OIIO::geterror(), "OpenImageIO does not recognise the file"));
    return readOpened(*in, check, context, out);
  });
}

int lensrt_oiio_read_memory(const void* bytes, size_t size, const char* format, lensrt_oiio_size_check check,
                            void* context, lensrt_oiio_image* out) {
  return guarded([&] {
    if (std::string_view(format) == "dpx")
      checkDpxHeader(static_cast<const unsigned char*>(bytes), size, size);
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
