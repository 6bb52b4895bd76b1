// Untrusted scenes through the command (issue 27): refused files are never
// opened (strace), a scene's own subfolders still work, and
// --allow-external-files, LENSRT_ALLOW_EXTERNAL_FILES and the scene digest
// follow the same rule.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "api/scene_digest.h"
#include "cli/cli_util.h"
#include "core/error.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;
using cli::runLensrt;
using cli::RunResult;
using cli::TempDir;

constexpr float kTriangle[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
constexpr unsigned short kIndices[3] = {0, 1, 2};
const std::string kConfined =
    "; a scene reads only files in its own folder (--allow-external-files lifts this)";

// A triangle scene in DIR/scene whose buffer is `uri`, and the bytes that buffer
// must hold (DIR/outside/secret-geometry.bin holds them).
struct Scene {
  fs::path folder, outside, secret;
  nlohmann::json doc;
  std::string bin;

  explicit Scene(const TempDir& dir) : folder(dir / "scene"), outside(dir / "outside") {
    fs::create_directories(folder);
    fs::create_directories(outside);
    doc = nlohmann::json::parse(cli::triangleGltf(kTriangle, kIndices));
    const std::string uri = doc["buffers"][0]["uri"];
    bin = decode(uri.substr(uri.find(',') + 1));
    secret = outside / "secret-geometry.bin";
    cli::writeFile(secret, bin);
  }

  fs::path withBuffer(const std::string& uri) const {
    nlohmann::json d = doc;
    d["buffers"][0]["uri"] = uri;
    const fs::path file = folder / "scene.gltf";
    cli::writeFile(file, d.dump());
    return file;
  }

  static std::string decode(const std::string& text) {
    const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::uint32_t acc = 0;
    int bits = 0;
    for (const char c : text) {
      if (c == '=') break;
      acc = (acc << 6) | std::uint32_t(table.find(c));
      bits += 6;
      if (bits >= 8) {
        bits -= 8;
        out += char((acc >> bits) & 0xFF);
      }
    }
    return out;
  }
};

std::vector<std::string> renderArgs(const fs::path& scene, const fs::path& out) {
  return {"render", scene.string(), "--res", "8x8", "--spp", "1", "-q", "-o", out.string()};
}

// lensrt under strace: the exit status and stderr, and every open call.
struct Traced {
  int status = -1;
  std::string err, opens;
};

std::optional<Traced> traced(const std::vector<std::string>& args, const TempDir& dir) {
  if (std::system("strace -qq -e trace=openat true >/dev/null 2>&1") != 0) return std::nullopt;
  // LeakSanitizer cannot work under ptrace (the sanitizer build); the other tests check leaks.
  std::string command =
      "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" strace -f -qq -e "
      "trace=open,openat,openat2,creat -o '" +
      (dir / "trace").string() + "' '" + LENSRT_BINARY + "'";
  for (const std::string& a : args) command += " '" + a + "'";
  command += " 2>'" + (dir / "stderr").string() + "'";
  const int raw = std::system(command.c_str());
  Traced t;
  t.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  t.err = cli::readFile(dir / "stderr");
  t.opens = cli::readFile(dir / "trace");
  return t;
}

// Each refusal comes from the path and the file's metadata alone: no open()
// call names the file (or the link, or the FIFO) the scene asked for.
TEST(UntrustedScene, RefusedFilesAreNeverOpened) {
  const TempDir dir;
  const Scene s(dir);
  const std::string secret = s.secret.string();
  fs::create_symlink(s.secret, s.folder / "link.bin");
  ASSERT_EQ(::mkfifo((s.folder / "pipe.bin").c_str(), 0600), 0);
  struct Case {
    std::string uri, message, unopened;
    std::vector<std::string> extra;
  };
  const std::vector<Case> cases = {
      {secret, "URI '" + secret + "': an absolute path" + kConfined, "secret-geometry.bin", {}},
      {"../outside/secret-geometry.bin",
       "URI '../outside/secret-geometry.bin': '..' climbs out of the scene's folder" + kConfined,
       "secret-geometry.bin",
       {}},
      {"file://" + secret,
       "URI 'file://" + secret +
           "': a file: URI; a scene names its files by relative paths (or holds them in data: URIs)",
       "secret-geometry.bin",
       {}},
      {"link.bin",
       "URI 'link.bin': a symbolic link that leads out of the scene's folder" + kConfined,
       "secret-geometry.bin",
       {}},
      {"pipe.bin", "URI 'pipe.bin': a FIFO, not a regular file", "pipe.bin", {}},
      {"/dev/zero",
       "URI '/dev/zero': a device file, not a regular file",
       "/dev/zero",
       {"--allow-external-files"}},
  };
  for (const Case& c : cases) {
    const fs::path scene = s.withBuffer(c.uri);
    std::vector<std::string> args = renderArgs(scene, dir / "out.exr");
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const std::optional<Traced> t = traced(args, dir);
    if (!t) GTEST_SKIP() << "strace cannot run here";
    EXPECT_EQ(t->status, 1) << c.uri;
    EXPECT_EQ(t->err, "lensrt: error: " + scene.string() + ": " + c.message + "\n") << c.uri;
    EXPECT_EQ(t->opens.find(c.unopened), std::string::npos) << c.uri << ":\n" << t->opens;
    EXPECT_NE(t->opens.find("scene.gltf"), std::string::npos) << "strace saw no open at all";
  }
  // The control: allowed, the same file is opened, read and named.
  const std::optional<Traced> t = traced({"render", s.withBuffer(secret).string(), "--res", "8x8", "--spp",
                                          "1", "--allow-external-files", "-o", (dir / "out.exr").string()},
                                         dir);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->status, 0) << t->err;
  EXPECT_NE(t->opens.find("secret-geometry.bin"), std::string::npos);
  EXPECT_NE(t->err.find("lensrt: warning: " + (s.folder / "scene.gltf").string() + ": reading " +
                        fs::canonical(s.secret).string() +
                        ", outside the scene's folder (--allow-external-files)\n"),
            std::string::npos)
      << t->err;
}

// A scene in a subfolder of a project, its textures in a subfolder of its
// own, renders as before (the texture decodes: no warning names it).
TEST(UntrustedScene, ASceneWithTexturesInASubfolderRenders) {
  const TempDir dir;
  const fs::path folder = dir / "project" / "scenes" / "room";
  fs::create_directories(folder / "textures");
  nlohmann::json d = nlohmann::json::parse(cli::triangleGltf(kTriangle, kIndices));
  cli::writeFile(folder / "textures" / "x.png",
                 Scene::decode("iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAAD0lEQVR4nGNoaGhg+A8EABR/"
                               "BX1DblR6AAAAAElFTkSuQmCC"));
  d["images"] = {{{"uri", "textures/x.png"}}};
  d["textures"] = {{{"source", 0}}};
  d["materials"] = {{{"emissiveTexture", {{"index", 0}}}, {"emissiveFactor", {1, 1, 1}}}};
  d["meshes"][0]["primitives"][0]["material"] = 0;
  cli::writeFile(folder / "room.gltf", d.dump());
  const RunResult r = runLensrt({"render", (folder / "room.gltf").string(), "--res", "8x8", "--spp", "1",
                                 "--env", "constant:1", "-o", (dir / "out.exr").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("x.png"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(dir / "out.exr"));
}

// For farm jobs that need a shared texture library: the variable lifts the
// confinement as the flag does; a value that is not a boolean is a usage error.
TEST(UntrustedScene, AllowExternalFilesFromTheEnvironment) {
  const TempDir dir;
  const Scene s(dir);
  const fs::path scene = s.withBuffer(s.secret.string());
  const std::vector<std::string> args = renderArgs(scene, dir / "out.exr");
  ::setenv("LENSRT_ALLOW_EXTERNAL_FILES", "1", 1);
  const RunResult allowed = runLensrt(args);
  ::setenv("LENSRT_ALLOW_EXTERNAL_FILES", "0", 1);
  const RunResult refused = runLensrt(args);
  ::setenv("LENSRT_ALLOW_EXTERNAL_FILES", "maybe", 1);
  const RunResult wrong = runLensrt(args);
  ::unsetenv("LENSRT_ALLOW_EXTERNAL_FILES");
  const RunResult unset = runLensrt(args);
  EXPECT_EQ(allowed.status, 0) << allowed.err;
  EXPECT_EQ(refused.status, 1) << refused.err;
  EXPECT_EQ(refused.err, "lensrt: error: " + scene.string() + ": URI '" + s.secret.string() +
                             "': an absolute path" + kConfined + "\n");
  EXPECT_EQ(wrong.status, 2) << wrong.err;
  EXPECT_EQ(unset.status, 1) << unset.err;
}

TEST(UntrustedScene, HelpShowsTheFlagsWithUnitsAndDefaults) {
  const RunResult r = runLensrt({"render", "--help"});
  EXPECT_EQ(r.status, 0);
  for (const char* text : {"--allow-external-files", "LENSRT_ALLOW_EXTERNAL_FILES", "--max-texture-memory",
                           "MiB the scene's textures may take", "default: half this machine's memory"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text << "\n" << r.out;
}

// The digest that identifies a render's parts reads the scene's files too:
// it follows the same confinement.
TEST(UntrustedScene, TheSceneDigestReadsOnlyWhatTheSceneMay) {
  const TempDir dir;
  const Scene s(dir);
  const std::string scene = s.withBuffer(s.secret.string()).string();
  try {
    sceneDigest(scene, "", false);
    ADD_FAILURE() << "the digest read a file outside the scene's folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.message(), "URI '" + s.secret.string() + "': an absolute path" + kConfined);
  }
  const std::string before = sceneDigest(scene, "", true);
  cli::writeFile(s.secret, s.bin + "x");
  EXPECT_NE(sceneDigest(scene, "", true), before);
}

}  // namespace
}  // namespace lensrt
