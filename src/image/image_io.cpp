#include "image/image_io.h"

#include <OpenImageIO/imageio.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include "core/error.h"
#include "image/srgb.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

enum class FileKind { Exr, Png, Jpeg, Unknown };

std::string lowerExtension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

FileKind kindOf(const fs::path& file) {
  const std::string ext = lowerExtension(file);
  if (ext == ".exr") return FileKind::Exr;
  if (ext == ".png") return FileKind::Png;
  if (ext == ".jpg" || ext == ".jpeg") return FileKind::Jpeg;
  return FileKind::Unknown;
}

// OIIO error texts can span lines; InputError promises one.
std::string oneLine(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s.empty() ? "unknown OpenImageIO error" : s;
}

std::string errnoReason(int err) {
  if (err == ENOSPC) return "disk full";
  if (err == EACCES || err == EPERM) return "permission denied";
  if (err == EROFS) return "read-only file system";
  return std::strerror(err);
}

// A hidden temporary file beside `file` (same file system, so the final
// rename is atomic), created exclusively so two writers never share one.
// Created with mode 0666 so the umask applies as for any new file.
fs::path createTemporaryBeside(const fs::path& file) {
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::random_device entropy;
  for (int attempt = 0; attempt < 16; ++attempt) {
    // Built with += : GCC 12 warns falsely (-Wrestrict) on a chain of operator+.
    std::string name = ".";
    name += file.filename().string();
    name += ".tmp" + std::to_string(::getpid()) + "-" + std::to_string(entropy() & 0xffffff);
    name += file.extension().string();
    const fs::path tmp = dir / name;
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return tmp;
    }
    if (errno != EEXIST) throw InputError(file.string(), "cannot create the file: " + errnoReason(errno));
  }
  throw InputError(file.string(), "cannot create a unique temporary file beside it");
}

// Removes the temporary unless the write completed and renamed it.
class TemporaryFile {
 public:
  explicit TemporaryFile(fs::path path) : path_(std::move(path)) {}
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (!path_.empty()) {
      std::error_code ignored;
      fs::remove(path_, ignored);
    }
  }
  const fs::path& path() const { return path_; }
  void release() { path_.clear(); }

 private:
  fs::path path_;
};

// The 8-bit preview's R,G,B source channels: R,G,B by name, else a single
// channel shown as grey, else the first three.
std::vector<int> previewChannels(const Image& image) {
  const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  if (r >= 0 && g >= 0 && b >= 0) return {r, g, b};
  if (image.channelCount() == 1) return {0, 0, 0};
  if (image.channelCount() >= 3) return {0, 1, 2};
  return {};
}

void writeToTemporary(const fs::path& file, const fs::path& tmp, FileKind kind, const Image& image,
                      const ImageMetadata& metadata, const ImageWriteOptions& options) {
  const char* format = kind == FileKind::Exr ? "openexr" : kind == FileKind::Png ? "png" : "jpeg";
  auto out = OIIO::ImageOutput::create(format);
  if (!out) throw InputError(file.string(), "OpenImageIO cannot write " + std::string(format) + " files");

  std::vector<float> previewPixels;
  const float* data = image.pixels.data();
  OIIO::ImageSpec spec;
  if (kind == FileKind::Exr) {
    spec = OIIO::ImageSpec(image.width, image.height, int(image.channelCount()),
                           options.halfFloat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
    spec.channelnames = image.channels;
    spec.alpha_channel = image.channelIndex("A");
    spec.attribute("compression", "zip");
    // A crop or tile: the data window inside the full frame's display window.
    spec.x = image.originX;
    spec.y = image.originY;
    spec.full_x = 0;
    spec.full_y = 0;
    spec.full_width = image.fullWidth();
    spec.full_height = image.fullHeight();
  } else {
    const std::vector<int> source = previewChannels(image);
    if (source.empty())
      throw InputError(file.string(), "a .png/.jpg preview needs R,G,B channels, a single channel or three");
    spec = OIIO::ImageSpec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("oiio:ColorSpace", "sRGB");
    if (kind == FileKind::Jpeg) spec.attribute("CompressionQuality", 95);
    // Encode here rather than letting OIIO quantise linear values, so the
    // preview is in sRGB whatever OIIO's colour defaults are.
    previewPixels.resize(std::size_t(image.width) * image.height * 3);
    const std::size_t pixelCount = std::size_t(image.width) * image.height;
    for (std::size_t i = 0; i < pixelCount; ++i)
      for (int c = 0; c < 3; ++c)
        previewPixels[i * 3 + c] = srgbEncode8(image.pixels[i * image.channelCount() + source[c]]) / 255.0f;
    data = previewPixels.data();
  }
  for (const auto& [key, value] : metadata) spec.attribute(key, value);

  if (!out->open(tmp.string(), spec))
    throw InputError(file.string(), "cannot write: " + oneLine(out->geterror()));
  const bool written = out->write_image(OIIO::TypeDesc::FLOAT, data);
  const std::string writeError = written ? "" : out->geterror();
  const bool closed = out->close();
  if (!written || !closed)
    throw InputError(file.string(), "cannot write: " + oneLine(written ? out->geterror() : writeError));
}

}  // namespace

bool isWritableImageExtension(const fs::path& file) {
  return kindOf(file) != FileKind::Unknown;
}

void writeImage(const fs::path& file, const Image& image, const ImageMetadata& metadata,
                const ImageWriteOptions& options) {
  const FileKind kind = kindOf(file);
  if (kind == FileKind::Unknown)
    throw InputError(file.string(),
                     "unknown image extension '" + file.extension().string() + "' (use .exr, .png or .jpg)");
  if (image.width <= 0 || image.height <= 0 || image.channels.empty() ||
      image.pixels.size() != std::size_t(image.width) * image.height * image.channelCount())
    throw InputError(file.string(), "cannot write an empty or inconsistent image (" +
                                        std::to_string(image.width) + "x" + std::to_string(image.height) +
                                        ", " + std::to_string(image.channelCount()) + " channels, " +
                                        std::to_string(image.pixels.size()) + " values)");
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(file.string(), "directory does not exist: " + dir.string());
  if (fs::is_directory(file, ec)) throw InputError(file.string(), "is a directory");

  TemporaryFile tmp(createTemporaryBeside(file));
  writeToTemporary(file, tmp.path(), kind, image, metadata, options);
  fs::rename(tmp.path(), file, ec);
  if (ec) throw InputError(file.string(), "cannot replace the file: " + ec.message());
  tmp.release();
}

Image readImage(const fs::path& file, ImageMetadata* metadata) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(file.string(), "no such file");
  if (fs::is_directory(file, ec)) throw InputError(file.string(), "is a directory");
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw InputError(file.string(), "cannot read image: " + oneLine(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.depth > 1) throw InputError(file.string(), "volume images are not supported");

  Image image(spec.width, spec.height, spec.channelnames);
  // The data window relative to the display window's corner; a file whose
  // display window is the data window is a whole frame.
  image.originX = spec.x - spec.full_x;
  image.originY = spec.y - spec.full_y;
  if (spec.full_width != spec.width || spec.full_height != spec.height || image.originX || image.originY) {
    image.frameWidth = spec.full_width;
    image.frameHeight = spec.full_height;
  }
  for (std::size_t c = 0; c < image.channels.size(); ++c)
    if (image.channels[c].empty()) image.channels[c] = "channel" + std::to_string(c);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw InputError(file.string(), "cannot read pixels: " + oneLine(in->geterror()));
  if (metadata) {
    metadata->clear();
    for (const OIIO::ParamValue& p : spec.extra_attribs) (*metadata)[p.name().string()] = p.get_string();
  }
  in->close();
  return image;
}

}  // namespace lensrt
