// Untrusted scenes (issue 27): a glTF reads only regular files inside its own
// folder. Each refused file outside holds exactly the bytes the scene asks
// for, so a loader that read it would succeed: these tests fail without the
// confinement. The links and the FIFO are made at run time.
#include "scene/scene_file_access.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <future>

#include "core/error.h"
#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::GltfBuilder;

const std::string kConfined =
    "; a scene reads only files in its own folder (--allow-external-files lifts this)";

// A folder with the scene and a sibling folder the scene must not read, which
// holds secret.bin: the square's geometry, byte for byte.
struct Folders {
  fs::path root = test::testDir();
  fs::path scene = root / "scene";
  fs::path outside = root / "outside";
  std::vector<std::uint8_t> bin;
  json doc;

  Folders() {
    GltfBuilder b;
    b.node({{"mesh", b.square()}});
    doc = json::parse(b.json());
    bin = b.bin;
    fs::create_directories(scene);
    fs::create_directories(outside);
    test::writeFile(outside / "secret.bin", bin);
  }

  // scene/NAME whose one buffer is `uri`.
  fs::path withBuffer(const std::string& uri, const std::string& name = "scene.gltf") const {
    json d = doc;
    d["buffers"][0]["uri"] = uri;
    d["buffers"][0]["byteLength"] = bin.size();
    return test::writeFile(scene / name, d.dump());
  }
};

// The message of the InputError loading `file` throws ("" if it loads).
std::string errorOf(const fs::path& file, const SceneReadLimits& limits = {}) {
  Warnings w;
  try {
    loadGltf(file, -1, w, limits);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    return e.message();
  }
  return "";
}

std::vector<std::uint8_t> fromBase64(const std::string& text) {
  const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  std::uint32_t acc = 0;
  int bits = 0;
  for (const char c : text) {
    if (c == '=') break;
    acc = (acc << 6) | std::uint32_t(table.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(std::uint8_t((acc >> bits) & 0xFF));
    }
  }
  return out;
}

SceneReadLimits allowingExternalFiles() {
  SceneReadLimits limits;
  limits.allowExternalFiles = true;
  return limits;
}

TEST(SceneFileAccess, PathsOutOfTheFolderAreRefused) {
  const Folders f;
  const std::string secret = (f.outside / "secret.bin").string();
  const std::string schemes = "; a scene names its files by relative paths (or holds them in data: URIs)";
  struct Case {
    std::string uri, message;
    bool lifted;  // by --allow-external-files
  };
  const std::vector<Case> cases = {
      {secret, "URI '" + secret + "': an absolute path" + kConfined, true},
      {"../outside/secret.bin",
       "URI '../outside/secret.bin': '..' climbs out of the scene's folder" + kConfined, true},
      {"sub/../../outside/secret.bin",
       "URI 'sub/../../outside/secret.bin': '..' climbs out of the scene's folder" + kConfined, true},
      // Percent escapes are decoded first, as tinygltf decodes them.
      {"%2E%2E/outside/secret.bin",
       "URI '../outside/secret.bin': '..' climbs out of the scene's folder" + kConfined, true},
      {"file://" + secret, "URI 'file://" + secret + "': a file: URI" + schemes, false},
      {"http://example.com/secret.bin", "URI 'http://example.com/secret.bin': a http: URI" + schemes, false},
      {"secret.bin%00.png", "URI 'secret.bin?.png': the path holds a NUL character", false},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(errorOf(f.withBuffer(c.uri)), c.message) << c.uri;
    EXPECT_EQ(errorOf(f.withBuffer(c.uri), allowingExternalFiles()), c.lifted ? "" : c.message) << c.uri;
  }
  // Inside the folder, '..' is only a detour.
  fs::create_directories(f.scene / "sub");
  test::writeFile(f.scene / "geometry.bin", f.bin);
  EXPECT_EQ(errorOf(f.withBuffer("sub/../geometry.bin")), "");
}

TEST(SceneFileAccess, SymbolicLinksOutOfTheFolderAreRefused) {
  const Folders f;
  fs::create_symlink(f.outside / "secret.bin", f.scene / "absolute-link.bin");
  fs::create_symlink("../outside/secret.bin", f.scene / "relative-link.bin");
  fs::create_directory_symlink(f.outside, f.scene / "library");
  fs::create_symlink(f.outside / "missing.bin", f.scene / "dangling.bin");
  for (const std::string uri : {"absolute-link.bin", "relative-link.bin", "library/secret.bin",
                                "library/missing.bin", "dangling.bin"})
    EXPECT_EQ(errorOf(f.withBuffer(uri)),
              "URI '" + uri + "': a symbolic link that leads out of the scene's folder" + kConfined);
  EXPECT_EQ(errorOf(f.withBuffer("library/secret.bin"), allowingExternalFiles()), "");
  // A link that stays inside is a file of the scene.
  fs::create_directories(f.scene / "geometry");
  test::writeFile(f.scene / "geometry" / "real.bin", f.bin);
  fs::create_symlink("geometry/real.bin", f.scene / "alias.bin");
  EXPECT_EQ(errorOf(f.withBuffer("alias.bin")), "");
}

// Opening a FIFO for reading blocks until a writer comes: the check must come
// before any open(). A load that blocks fails here after 20 s and is released.
TEST(SceneFileAccess, FifosAreRefusedWithoutBeingOpened) {
  const Folders f;
  ASSERT_EQ(::mkfifo((f.scene / "pipe.bin").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((f.outside / "pipe.bin").c_str(), 0600), 0);
  fs::create_symlink(f.outside / "pipe.bin", f.scene / "outside-pipe.bin");
  struct Case {
    std::string uri;
    SceneReadLimits limits;
    std::string message;
    fs::path fifo;
  };
  const std::vector<Case> cases = {
      {"pipe.bin", {}, "URI 'pipe.bin': a FIFO, not a regular file", f.scene / "pipe.bin"},
      {"pipe.bin", allowingExternalFiles(), "URI 'pipe.bin': a FIFO, not a regular file",
       f.scene / "pipe.bin"},
      {"outside-pipe.bin",
       {},
       "URI 'outside-pipe.bin': a symbolic link that leads out of the scene's folder" + kConfined,
       f.outside / "pipe.bin"},
  };
  for (const Case& c : cases) {
    const fs::path scene = f.withBuffer(c.uri);
    auto load = std::async(std::launch::async, [&] { return errorOf(scene, c.limits); });
    if (load.wait_for(std::chrono::seconds(20)) == std::future_status::timeout) {
      ADD_FAILURE() << c.uri << ": the load blocked (the FIFO was opened)";
      // A writer that comes and goes releases each blocked open.
      for (int i = 0; i < 1000 && load.wait_for(std::chrono::milliseconds(10)) == std::future_status::timeout;
           ++i) {
        const int writer = ::open(c.fifo.c_str(), O_WRONLY | O_NONBLOCK);
        if (writer >= 0) ::close(writer);
      }
    }
    EXPECT_EQ(load.get(), c.message) << c.uri;
  }
}

TEST(SceneFileAccess, AllowedExternalFilesAreReadAndNamed) {
  const Folders f;
  const fs::path secret = fs::canonical(f.outside / "secret.bin");
  Warnings w;
  EXPECT_NO_THROW(loadGltf(f.withBuffer(secret.string()), -1, w, allowingExternalFiles()));
  EXPECT_EQ(
      w.all().count("reading " + secret.string() + ", outside the scene's folder (--allow-external-files)"),
      1u);
  // Files that are no regular file stay refused.
  EXPECT_EQ(errorOf(f.withBuffer("/dev/zero"), allowingExternalFiles()),
            "URI '/dev/zero': a device file, not a regular file");
  EXPECT_EQ(errorOf(f.withBuffer("/dev/zero")), "URI '/dev/zero': an absolute path" + kConfined);
}

// tinygltf looks for a URI it does not find beside the scene in the working
// directory too; lensrt never does.
TEST(SceneFileAccess, TheWorkingDirectoryIsNotSearched) {
  const Folders f;
  test::writeFile(f.outside / "geometry.bin", f.bin);
  const fs::path scene = f.withBuffer("geometry.bin");
  const fs::path cwd = fs::current_path();
  fs::current_path(f.outside);
  const std::string message = errorOf(scene);
  const std::string relativeMessage = errorOf(fs::relative(scene, f.outside));
  fs::current_path(cwd);
  EXPECT_EQ(message, "File not found : geometry.bin");
  EXPECT_EQ(relativeMessage, "File not found : geometry.bin");
}

// A scene with its textures in a subfolder, named with escapes, loads; an image
// outside the folder is an error like a buffer outside it.
TEST(SceneFileAccess, ImagesAreConfinedLikeBuffers) {
  const Folders f;
  json d = f.doc;
  d["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  d["textures"] = {{{"source", 0}}};
  d["meshes"][0]["primitives"][0]["material"] = 0;
  fs::create_directories(f.scene / "textures");
  const std::vector<std::uint8_t> pngBytes = fromBase64(test::kTwoTexelPngBase64);
  test::writeFile(f.scene / "textures" / "my tex.png", pngBytes);
  test::writeFile(f.outside / "tex.png", pngBytes);
  d["images"] = {{{"uri", "textures/my%20tex.png"}}};
  Warnings w;
  const SceneDesc desc = loadGltf(test::writeFile(f.scene / "textured.gltf", d.dump()), -1, w);
  ASSERT_EQ(desc.textures.size(), 1u);
  EXPECT_EQ(desc.textures[0].width, 2);
  const std::string outside = (f.outside / "tex.png").string();
  d["images"] = {{{"uri", outside}}};
  EXPECT_EQ(errorOf(test::writeFile(f.scene / "textured.gltf", d.dump())),
            "URI '" + outside + "': an absolute path" + kConfined);
}

TEST(SceneFileAccess, DataUrisOverTheLimitAreRefused) {
  const Folders f;
  SceneReadLimits limits;
  limits.maxDataUriBytes = 10;
  GltfBuilder b;
  b.node({{"mesh", b.square()}});
  const fs::path embedded = test::writeFile(f.scene / "embedded.gltf", b.json());
  EXPECT_EQ(errorOf(embedded, limits), "buffer 0: its data: URI decodes to " + std::to_string(b.bin.size()) +
                                           " bytes, more than the 10 a data: URI may hold");
  EXPECT_EQ(errorOf(embedded), "");
  // An image's data: URI (the buffer a file beside the scene).
  json d = f.doc;
  test::writeFile(f.scene / "geometry.bin", f.bin);
  d["buffers"][0]["uri"] = "geometry.bin";
  d["images"] = {{{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}}};
  const std::size_t pngBytes = fromBase64(test::kTwoTexelPngBase64).size();
  EXPECT_EQ(errorOf(test::writeFile(f.scene / "image.gltf", d.dump()), limits),
            "image 0: its data: URI decodes to " + std::to_string(pngBytes) +
                " bytes, more than the 10 a data: URI may hold");
}

// Textures are held as 16 bytes a texel; the budget counts them all.
TEST(SceneFileAccess, TexturesOverTheBudgetAreRefused) {
  GltfBuilder b;
  b.doc["images"] = {{{"uri", std::string("data:image/png;base64,") + test::kTwoTexelPngBase64}}};
  b.doc["textures"] = {{{"source", 0}}};
  // The same image as colour (sRGB) and as data: two textures of 32 bytes.
  b.doc["materials"] = {
      {{"pbrMetallicRoughness",
        {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 0}}}}}}};
  b.node({{"mesh", b.square(0)}});
  const fs::path scene = test::writeFile(test::testDir() / "scene.gltf", b.json());
  SceneReadLimits limits;
  limits.maxTextureBytes = 31;
  EXPECT_EQ(errorOf(scene, limits),
            "texture image '#0' (2x1) brings the textures to 32 bytes, more than the 31 bytes "
            "--max-texture-memory allows");
  limits.maxTextureBytes = 32;
  EXPECT_EQ(errorOf(scene, limits),
            "texture image '#0' (2x1) brings the textures to 64 bytes, more than the 32 bytes "
            "--max-texture-memory allows");
  limits.maxTextureBytes = 64;
  EXPECT_EQ(errorOf(scene, limits), "");
}

TEST(SceneFileAccess, UrisAreDecodedAsTinygltfDecodesThem) {
  // '+' is a space; an invalid hex digit counts as 0; a '%' too near the end stays.
  EXPECT_EQ(decodeUriPath("a%20b+c%2Fd%2e%2E%zz%4"), std::string("a b c/d..") + '\0' + "%4");
}

}  // namespace
}  // namespace lensrt
