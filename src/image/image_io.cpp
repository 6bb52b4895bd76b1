#include "image/image_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <system_error>
#include <vector>

#include "core/ascii_lower.h"
#include "core/error.h"
#include "image/cineon.h"
#include "image/exr_io.h"
#include "image/oiio_plugin.h"
#include "image/output_formats.h"
#include "image/plugin_image_formats.h"
#include "image/plugin_input.h"
#include "image/plugin_output.h"
#include "image/srgb.h"
#include "image/stb_io.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;

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

// A preview's R,G,B source channels: R,G,B by name, else a single channel
// shown as grey, else the first three.
std::vector<int> previewChannels(const fs::path& file, const Image& image) {
  const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
  if (r >= 0 && g >= 0 && b >= 0) return {r, g, b};
  if (image.channelCount() == 1) return {0, 0, 0};
  if (image.channelCount() >= 3) return {0, 1, 2};
  throw InputError(file.string(), "a preview needs R,G,B channels, a single channel or three");
}

// The file's bytes, encoded in memory so that writing them is one checked
// step (a full disk is reported, not half-written).
std::string encode(const fs::path& file, const OutputFormat& format, const Image& image,
                   const ImageMetadata& metadata, const ImageWriteOptions& options) {
  if (format.encoder == ImageEncoder::Exr)
    return encodeExr(file.string(), image, metadata, options.halfFloat);
  const std::vector<float> values = previewValues(file, image, previewChannels(file, image), options.display);
  std::string rgb(values.size(), '\0');
  for (std::size_t i = 0; i < values.size(); ++i) rgb[i] = char(std::lround(values[i] * 255.0f));
  return encodePreview(file.string(),
                       format.encoder == ImageEncoder::Png ? PreviewFormat::Png : PreviewFormat::Jpeg,
                       image.width, image.height, rgb, metadata);
}

void writeBytes(const fs::path& file, const fs::path& tmp, const std::string& bytes) {
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  if (fd < 0) throw InputError(file.string(), "cannot write: " + errnoReason(errno));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      throw InputError(file.string(), "cannot write: " + errnoReason(err));
    }
    done += std::size_t(n);
  }
  if (::close(fd) != 0) throw InputError(file.string(), "cannot write: " + errnoReason(errno));
}

std::string readHead(const fs::path& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open: " + errnoReason(errno));
  std::string head(n, '\0');
  in.read(head.data(), std::streamsize(n));
  head.resize(std::size_t(in.gcount()));
  return head;
}

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot open: " + errnoReason(errno));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(file.string(), "cannot read the file");
  return bytes;
}

}  // namespace

bool isWritableImageExtension(const fs::path& file) {
  return outputFormatFor(file) != nullptr;
}

bool isReadableImageExtension(const fs::path& file) {
  const std::string ext = lowerExtension(file);
  return ext == ".exr" || ext == ".hdr" || ext == ".png" || ext == ".jpg" || ext == ".jpeg" ||
         isPluginInputExtension(file);
}

void writeImage(const fs::path& file, const Image& image, const ImageMetadata& metadata,
                const ImageWriteOptions& options) {
  const OutputFormat* format = outputFormatFor(file);
  if (!format)
    throw InputError(file.string(), "unknown image extension '" + file.extension().string() + "' (use " +
                                        outputExtensionList() + ")");
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

  if (format->encoder == ImageEncoder::Plugin) {
    const std::vector<int> source = previewChannels(file, image);
    writeFileThrough(file, [&](const fs::path& tmp) {
      writeWithPlugin(file, tmp, *format, image, source, metadata, options.display);
    });
    return;
  }
  const std::string bytes = encode(file, *format, image, metadata, options);
  TemporaryFile tmp(createTemporaryBeside(file));
  writeBytes(file, tmp.path(), bytes);
  fs::rename(tmp.path(), file, ec);
  if (ec) throw InputError(file.string(), "cannot replace the file: " + ec.message());
  tmp.release();
}

void writeFileThrough(const fs::path& file, const std::function<void(const fs::path&)>& write) {
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(file.string(), "directory does not exist: " + dir.string());
  if (fs::is_directory(file, ec)) throw InputError(file.string(), "is a directory");
  TemporaryFile tmp(createTemporaryBeside(file));
  write(tmp.path());
  fs::rename(tmp.path(), file, ec);
  if (ec) throw InputError(file.string(), "cannot replace the file: " + ec.message());
  tmp.release();
}

void checkDisplayTransform(const fs::path& file, const DisplayTransform& display) {
  const OutputFormat* format = outputFormatFor(file);
  if (!format || format->role != ImageRole::Preview) {
    std::string why = "applies to previews (" + outputExtensionList(ImageRole::Preview, ", ") + "), not ";
    why += file.extension().string();
    why += " files (scene-linear or log)";
    throw UsageError("--ocio-display", why);
  }
  Image probe(1, 1, {"R", "G", "B"});
  previewValues(file, probe, {0, 1, 2}, display);
}

void checkImageWriter(const fs::path& file) {
  if (const OutputFormat* format = outputFormatFor(file); format && format->encoder == ImageEncoder::Plugin) {
    std::string purpose = "writing ";
    purpose += format->label;
    purpose += " files";
    OiioPlugin::get(file.string(), purpose);
  }
}

namespace {

std::optional<PluginFormat> sniffedPluginFormat(std::string_view bytes) {
  return sniffPluginFormat(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

// Radiance files hold linear light; stb_image's other formats sRGB codes.
bool looksLikeRadiance(std::string_view bytes) {
  return bytes.rfind("#?RADIANCE", 0) == 0 || bytes.rfind("#?RGBE", 0) == 0;
}

// The label of the format a file's extension names, for the plugin's
// messages: ".cin images".
std::string extensionLabel(const fs::path& file) {
  std::string label = file.extension().string();
  return label.empty() ? "these" : label;
}

EncodedImage readEncoded(const fs::path& file, ImageMetadata* metadata) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(file.string(), "no such file");
  if (fs::is_directory(file, ec)) throw InputError(file.string(), "is a directory");
  if (metadata) metadata->clear();
  const std::string head = readHead(file, 64);
  // EXR files are read through OpenEXR's own stream: renders can be large.
  if (looksLikeExr(head)) return {readExrFile(file, metadata, kMaxImageValues), StoredEncoding::Linear};
  if (const std::optional<PluginFormat> format = sniffedPluginFormat(head))
    return readWithPlugin(file, format->label, kMaxImageValues);
  const std::string bytes = readAll(file);
  if (!isStbImage(bytes) && isPluginInputExtension(file))
    return readWithPlugin(file, extensionLabel(file), kMaxImageValues);
  const StoredEncoding encoding = looksLikeRadiance(bytes) ? StoredEncoding::Linear : StoredEncoding::Srgb;
  return {decodeStbImage(bytes, file.string(), kMaxImageValues), encoding};
}

bool isAlpha(const std::string& channel) {
  return channel == "A" || (channel.size() > 2 && channel.compare(channel.size() - 2, 2, ".A") == 0);
}

}  // namespace

Image readImage(const fs::path& file, ImageMetadata* metadata) {
  return readEncoded(file, metadata).image;
}

void checkImageReader(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) return;  // the read says what is wrong
  if (const std::optional<PluginFormat> format = sniffedPluginFormat(readHead(file, 64))) {
    std::string purpose = "reading ";
    purpose += format->label;
    purpose += " images";
    OiioPlugin::get(file.string(), purpose);
  }
}

Image readLinearImage(const fs::path& file) {
  EncodedImage read = readEncoded(file, nullptr);
  if (read.encoding == StoredEncoding::Linear) return std::move(read.image);
  Image& image = read.image;
  const std::size_t channels = image.channelCount();
  for (std::size_t c = 0; c < channels; ++c) {
    if (isAlpha(image.channels[c])) continue;
    for (std::size_t i = c; i < image.pixels.size(); i += channels)
      image.pixels[i] = read.encoding == StoredEncoding::Cineon
                            ? cineonDecode(image.pixels[i] * cineon::kMaxCode)
                            : srgbDecode(image.pixels[i]);
  }
  return std::move(image);
}

Image decodeImage(std::string_view bytes, const std::string& name, ImageMetadata* metadata,
                  std::size_t maxValues) {
  if (metadata) metadata->clear();
  if (looksLikeExr(bytes)) return decodeExr(bytes, name, metadata, maxValues);
  if (const std::optional<PluginFormat> format = sniffedPluginFormat(bytes))
    return decodeWithPlugin(bytes, *format, name, maxValues).image;
  return decodeStbImage(bytes, name, maxValues);
}

}  // namespace lensrt
