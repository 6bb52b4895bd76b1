#include "scene/scene_file_access.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>

#include "core/error.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;

constexpr const char* kConfined =
    "; a scene reads only files in its own folder (--allow-external-files lifts this)";

unsigned char fromHex(unsigned char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return 0;
}

// "name:" before any '/': an RFC 3986 scheme (a letter, then letters, digits,
// '+', '-', '.'); empty when the URI has none.
std::string schemeOf(const std::string& uri) {
  const std::size_t colon = uri.find(':');
  if (colon == std::string::npos || colon == 0 || uri.find('/') < colon) return "";
  if (!std::isalpha(static_cast<unsigned char>(uri[0]))) return "";
  for (std::size_t i = 1; i < colon; ++i) {
    const auto c = static_cast<unsigned char>(uri[i]);
    if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return "";
  }
  return uri.substr(0, colon + 1);
}

// What a file that is not a regular file is, for the message.
std::string notRegular(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a directory, not a regular file";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device file, not a regular file";
    case fs::file_type::fifo:
      return "a FIFO, not a regular file";
    case fs::file_type::socket:
      return "a socket, not a regular file";
    default:
      return "not a regular file";
  }
}

// Closes the descriptor it holds.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

}  // namespace

std::uint64_t defaultMaxTextureBytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return std::uint64_t{4} << 30;  // unknown: 4 GiB
  return std::uint64_t(pages) * std::uint64_t(pageSize) / 2;
}

std::string decodeUriPath(const std::string& uri) {
  std::string out;
  out.reserve(uri.size());
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>((fromHex(static_cast<unsigned char>(uri[i + 1])) << 4) |
                               fromHex(static_cast<unsigned char>(uri[i + 2])));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

std::string uriForMessage(const std::string& uri) {
  constexpr std::size_t kLongest = 400;  // a path, not a whole data: URI
  std::string shown = uri.size() > kLongest ? uri.substr(0, kLongest - 3) + "..." : uri;
  // One line: control characters (a decoded %0A) as '?'.
  std::replace_if(
      shown.begin(), shown.end(), [](char c) { return std::iscntrl(static_cast<unsigned char>(c)); }, '?');
  return shown;
}

SceneFileAccess::SceneFileAccess(const fs::path& sceneFile, bool allowExternalFiles)
    : scene_(sceneFile.string()), allowExternal_(allowExternalFiles) {
  std::error_code ec;
  folder_ = fs::absolute(sceneFile, ec).lexically_normal().parent_path();
  realFolder_ = fs::weakly_canonical(folder_, ec);
  if (ec) realFolder_ = folder_;
}

void SceneFileAccess::refuse(const std::string& uri, const std::string& why) const {
  throw InputError(scene_, "URI '" + uriForMessage(uri) + "': " + why);
}

bool SceneFileAccess::inside(const fs::path& path) const {
  const auto [end, unused] = std::mismatch(realFolder_.begin(), realFolder_.end(), path.begin(), path.end());
  return end == realFolder_.end();
}

std::optional<SceneFile> SceneFileAccess::resolveDecoded(const std::string& uri) const {
  // The path alone first: nothing is looked up for what these refuse.
  if (uri.empty()) return std::nullopt;
  if (uri.find('\0') != std::string::npos) refuse(uri, "the path holds a NUL character");
  if (const std::string scheme = schemeOf(uri); !scheme.empty())
    refuse(uri,
           "a " + scheme + " URI; a scene names its files by relative paths (or holds them in data: URIs)");
  const fs::path given(uri);
  const fs::path relative = given.lexically_normal();
  if (given.is_absolute()) {
    if (!allowExternal_) refuse(uri, std::string("an absolute path") + kConfined);
  } else if (!relative.empty() && *relative.begin() == "..") {
    if (!allowExternal_) refuse(uri, std::string("'..' climbs out of the scene's folder") + kConfined);
  }
  SceneFile file;
  file.named = given.is_absolute() ? relative : (folder_ / relative).lexically_normal();
  // Symbolic links resolved as far as the path exists: a link out of the
  // folder is refused whether or not what it points to exists.
  std::error_code ec;
  file.resolved = fs::weakly_canonical(file.named, ec);
  if (ec) return std::nullopt;
  file.external = !inside(file.resolved);
  if (file.external && !allowExternal_)
    refuse(uri, std::string("a symbolic link that leads out of the scene's folder") + kConfined);
  const fs::file_status status = fs::status(file.resolved, ec);
  if (!fs::exists(status)) {
    // A dangling link: where it points decides, as for a link to a file.
    if (!allowExternal_ && fs::is_symlink(fs::symlink_status(file.resolved, ec))) {
      const fs::path target = fs::read_symlink(file.resolved, ec);
      if (!ec && !inside((file.resolved.parent_path() / target).lexically_normal()))
        refuse(uri, std::string("a symbolic link that leads out of the scene's folder") + kConfined);
    }
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) refuse(uri, notRegular(status.type()));
  struct stat st {};
  if (::stat(file.resolved.c_str(), &st) != 0) return std::nullopt;
  file.device = st.st_dev;
  file.inode = st.st_ino;
  return file;
}

std::vector<unsigned char> SceneFileAccess::read(const SceneFile& file) const {
  const std::string name = file.named.string();
  // O_NONBLOCK: a FIFO swapped in after the check must not hang the render.
  const FileDescriptor fd(::open(file.resolved.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY));
  struct stat st {};
  if (fd.get() < 0 || ::fstat(fd.get(), &st) != 0) throw InputError(name, "cannot open the file");
  if (!S_ISREG(st.st_mode) || st.st_dev != file.device || st.st_ino != file.inode)
    throw InputError(name, "the file changed while the scene was being read");
  std::vector<unsigned char> bytes(static_cast<std::size_t>(st.st_size));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::read(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw InputError(name, "cannot read the file");
    done += static_cast<std::size_t>(n);
  }
  return bytes;
}

}  // namespace lensrt
