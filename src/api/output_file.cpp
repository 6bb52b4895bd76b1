#include "api/output_file.h"

#include <fcntl.h>
#include <fmt/core.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <string>

#include "core/error.h"
#include "image/image_io.h"
#include "image/output_formats.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;

fs::path directoryOf(const fs::path& out) {
  return out.has_parent_path() ? out.parent_path() : fs::path(".");
}

// Bytes free for an unprivileged writer; -1 when unknown.
double freeBytes(const fs::path& dir) {
  struct statvfs s {};
  if (::statvfs(dir.c_str(), &s) != 0 || s.f_blocks == 0) return -1;
  return double(s.f_bavail) * double(s.f_frsize);
}

bool diskFull(const fs::path& dir) {
  return freeBytes(dir) == 0;
}

// Creates and removes an empty file beside `out`: access() says yes to root
// on read-only mounts and on /proc, where creating a file still fails.
void probeDirectory(const fs::path& out, const fs::path& dir) {
  // Appended piece by piece: GCC 12 misreads "." + std::string (bug 105329).
  std::string name = ".";
  name += out.filename().string();
  name += ".lensrt-probe-";
  name += std::to_string(::getpid());
  const fs::path probe = dir / name;
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
    return;
  }
  const int err = errno;
  const std::string notWritable = "the output directory " + dir.string() + " is not writable";
  if (err == EACCES || err == EPERM || err == EROFS) throw InputError(out.string(), notWritable);
  if (err == ENOSPC || err == EDQUOT)
    throw InputError(out.string(), "no space left on the disk holding " + dir.string());
  if (err == EEXIST) return;  // a leftover probe: the directory takes files
  throw InputError(out.string(), notWritable + " (creating a file there fails: " + std::strerror(err) + ")");
}

}  // namespace

std::optional<fs::path> createFolderFor(const fs::path& file) {
  const fs::path dir = directoryOf(file);
  std::error_code ec;
  if (fs::exists(dir, ec)) return std::nullopt;
  // A dangling symbolic link or a file on the way is create_directories' error.
  if (!fs::create_directories(dir, ec) && ec)
    throw InputError(file.string(), "cannot create the folder " + dir.string() + ": " + ec.message());
  return dir;
}

std::optional<fs::path> checkOutputFile(const fs::path& out) {
  std::error_code ec;
  if (fs::is_directory(out, ec))
    throw InputError(out.string(), "is a directory (-o takes an image file name, e.g. -o out/render.exr)");
  if (!isWritableImageExtension(out))
    throw UsageError(
        "-o", (out.extension().empty() ? "'" + out.string() + "' has no image extension"
                                       : "unknown image extension '" + out.extension().string() + "'") +
                  " (" + outputFormatAdvice() + ")");
  checkImageWriter(out);
  const std::optional<fs::path> created = createFolderFor(out);
  const fs::path dir = directoryOf(out);
  if (!fs::is_directory(dir, ec)) throw InputError(out.string(), dir.string() + " is not a directory");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(out.string(), "the output directory " + dir.string() + " is not writable");
  probeDirectory(out, dir);
  if (diskFull(dir)) throw InputError(out.string(), "no space left on the disk holding " + dir.string());
  return created;
}

void writeOutputImage(const fs::path& out, const Image& image, const ImageMetadata& metadata,
                      const ImageWriteOptions& options) {
  try {
    writeImage(out, image, metadata, options);
  } catch (const InputError& e) {
    // The failed write's temporary file is gone again: judge the space by
    // what the image needs uncompressed.
    const fs::path dir = directoryOf(out);
    const double free = freeBytes(dir);
    if (free >= 0 && free < double(image.pixels.size()) * sizeof(float) + 65536.0)
      throw InputError(out.string(),
                       fmt::format("cannot write: not enough space on the disk holding {} ({:.0f} KiB free)",
                                   dir.string(), free / 1024.0));
    // The image layer writes ".NAME.tmpPID-N.EXT" beside the file first; the
    // user asked for NAME.
    std::string message = e.message();
    const std::string tmpStart = (dir / ("." + out.filename().string() + ".tmp")).string();
    for (std::size_t at = message.find(tmpStart); at != std::string::npos; at = message.find(tmpStart, at)) {
      std::size_t end = at + tmpStart.size();
      while (end < message.size() &&
             (std::isdigit(static_cast<unsigned char>(message[end])) || message[end] == '-'))
        ++end;
      if (message.compare(end, out.extension().string().size(), out.extension().string()) == 0)
        end += out.extension().string().size();
      message.replace(at, end - at, out.string());
      at += out.string().size();
    }
    throw InputError(out.string(), message, e.line());
  }
}

}  // namespace lensrt
