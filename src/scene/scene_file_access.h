// What a scene's URIs may make lensrt read (issue 27). Scene files often come
// from other people (a render farm, a shared service), so by default a scene
// reads only regular files inside the folder of its .gltf/.glb (subfolders
// allowed): otherwise a buffer URI such as /etc/passwd would turn the render
// into a way to read files off the machine. Every reader that follows a URI
// (buffers, images, the scene digest, and any later one) resolves it here.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lensrt {

// Half the machine's physical memory: the default texture budget.
std::uint64_t defaultMaxTextureBytes();

// What a scene may make lensrt read and hold.
struct SceneReadLimits {
  // Lifts the folder confinement (--allow-external-files); non-regular files
  // (devices, FIFOs, sockets, directories) stay refused.
  bool allowExternalFiles = false;
  // Each data: URI, decoded: 256 MiB is far beyond an embedded asset.
  std::uint64_t maxDataUriBytes = std::uint64_t{256} << 20;
  // All textures together, as held for rendering (16 bytes a texel).
  std::uint64_t maxTextureBytes = defaultMaxTextureBytes();
};

// A file a URI names, checked and resolved.
struct SceneFile {
  std::filesystem::path named;     // the scene's folder joined with the URI's path, as written
  std::filesystem::path resolved;  // with every symbolic link resolved: what is opened
  bool external = false;           // outside the scene's folder (only when allowed)
  dev_t device = 0;                // what was checked, so that read() opens the same file
  ino_t inode = 0;
};

// A URI path decoded the way tinygltf decodes it before opening: %XX escapes
// (an invalid hex digit counts as 0) and '+' as a space.
std::string decodeUriPath(const std::string& uri);

// A URI as it appears in a message: one line, and past 400 characters (a
// data: URI, a made-up name) cut short.
std::string uriForMessage(const std::string& uri);

class SceneFileAccess {
 public:
  // `sceneFile`: the .gltf/.glb, named in errors as given.
  SceneFileAccess(const std::filesystem::path& sceneFile, bool allowExternalFiles);

  // The file a buffer or image URI names, or nullopt when there is no such
  // file. Throws InputError(scene, "URI 'uri': why") for a URI the scene may
  // not read, looking only at the path and the file's metadata, never opening
  // it: a scheme other than data: (data: URIs hold their bytes and name no
  // file; callers decode them), an absolute path, '..' climbing out of the
  // folder, a symbolic link leading out of it, and anything but a regular file.
  std::optional<SceneFile> resolve(const std::string& uri) const {
    return resolveDecoded(decodeUriPath(uri));
  }
  // The same for a URI that is already decoded (tinygltf hands its readers those).
  std::optional<SceneFile> resolveDecoded(const std::string& decodedUri) const;

  // The bytes of a resolved file. Opened without blocking and checked to be
  // the regular file resolve() looked at, so that a file swapped in between
  // (a FIFO, a link) is not read. Throws InputError.
  std::vector<unsigned char> read(const SceneFile& file) const;

  // The scene's folder, absolute, as tinygltf joins URIs to it.
  const std::filesystem::path& folder() const { return folder_; }

 private:
  [[noreturn]] void refuse(const std::string& uri, const std::string& why) const;
  bool inside(const std::filesystem::path& path) const;

  std::string scene_;
  std::filesystem::path folder_;      // absolute and lexically normal
  std::filesystem::path realFolder_;  // with symbolic links resolved
  bool allowExternal_;
};

}  // namespace lensrt
