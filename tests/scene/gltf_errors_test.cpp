// Bad input: one InputError with a one-line message naming the file, never a crash.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <random>
#include <sstream>

#include "core/error.h"
#include "gltf_test_builder.h"
#include "scene/gltf_loader.h"
#include "scene/selection_error.h"

namespace lensrt {
namespace {

using nlohmann::json;
using test::GltfBuilder;

// The message of the InputError that loading `file` throws ("" if none).
std::string errorOf(const std::filesystem::path& file, int scene = -1) {
  Warnings w;
  try {
    loadGltf(file, scene, w);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    EXPECT_EQ(e.message().find('\n'), std::string::npos) << e.message();
    return e.message();
  }
  return "";
}

std::string errorOf(const GltfBuilder& b, int scene = -1) {
  return errorOf(test::writeFile(test::testDir() / "bad.gltf", b.json()), scene);
}

GltfBuilder validSquare() {
  GltfBuilder b;
  b.node({{"mesh", b.square()}});
  return b;
}

TEST(GltfErrors, ValidBaselineLoads) {
  EXPECT_EQ(errorOf(validSquare()), "");
}

TEST(GltfErrors, MissingFile) {
  EXPECT_EQ(errorOf(test::testDir() / "nope.gltf"), "file not found");
}

TEST(GltfErrors, BrokenJsonReportsLineAndColumn) {
  const auto file = test::writeFile(test::testDir() / "bad.gltf",
                                    "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [}\n");
  Warnings w;
  try {
    loadGltf(file, -1, w);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.message().rfind("JSON syntax error at column 13: ", 0), 0u) << e.message();
    EXPECT_EQ(e.message().find('\n'), std::string::npos);
  }
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "empty.gltf", "")), "file is empty");
}

TEST(GltfErrors, MissingBin) {
  GltfBuilder b = validSquare();
  json d = json::parse(b.json());
  d["buffers"][0]["uri"] = "geometry.bin";
  const std::string msg = errorOf(test::writeFile(test::testDir() / "bad.gltf", d.dump()));
  EXPECT_NE(msg.find("geometry.bin"), std::string::npos) << msg;
}

TEST(GltfErrors, BufferShorterThanItsViews) {
  GltfBuilder b = validSquare();
  b.doc["bufferViews"][0]["byteLength"] = 4000;
  EXPECT_EQ(errorOf(b), "bufferView 0 (bytes 0..4000) exceeds buffer 0 of 92 bytes");
}

TEST(GltfErrors, AccessorBeyondItsView) {
  GltfBuilder b = validSquare();
  b.doc["accessors"][0]["count"] = 5;
  EXPECT_EQ(
      errorOf(b),
      "mesh '#0' POSITION (accessor 0): accessor reads beyond the end of bufferView 0 (5 elements of 12 "
      "bytes from offset 0, view is 48 bytes)");
}

TEST(GltfErrors, AccessorThatDoesNotExist) {
  GltfBuilder b = validSquare();
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 42;
  EXPECT_EQ(errorOf(b), "mesh '#0' NORMAL: accessor 42 does not exist");
}

TEST(GltfErrors, IndexBeyondVertexCount) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", b.u16({0, 1, 9})}})}});
  EXPECT_EQ(errorOf(b), "mesh '#0': index 9 beyond the vertex count 3");
}

TEST(GltfErrors, NanPosition) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, std::nanf(""), 0, 0, 0, 1, 0}, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}})}});
  EXPECT_EQ(errorOf(b), "mesh '#0': vertex position is NaN or infinite");
}

TEST(GltfErrors, HugeCoordinates) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1e20f, 0, 0, 0, 1, 0}, "VEC3");
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}})}});
  EXPECT_EQ(errorOf(b), "mesh '#0': vertex coordinate beyond 1e15");
  GltfBuilder scaled = validSquare();
  scaled.doc["nodes"][0]["scale"] = {1e16, 1, 1};
  EXPECT_EQ(errorOf(scaled), "world-space coordinates beyond 1e15 (check the node transforms)");
}

TEST(GltfErrors, NoMeshes) {
  GltfBuilder b;
  b.node({{"name", "empty"}});
  EXPECT_EQ(errorOf(b), "nothing to render: the file has no meshes");
}

TEST(GltfErrors, CameraWithoutMeshesRendersTheEnvironment) {
  GltfBuilder b;
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  b.node({{"name", "flat field"}, {"camera", 0}});
  Warnings w;
  const SceneDesc d = loadGltf(test::writeFile(test::testDir() / "sky.gltf", b.json()), -1, w);
  EXPECT_TRUE(d.instances.empty());
  EXPECT_EQ(d.cameras.size(), 1u);
  EXPECT_EQ(w.all(), (std::set<std::string>{"the scene has no meshes: rendering the environment only"}));
}

TEST(GltfErrors, AssetVersionMustBeTwo) {
  const auto withAsset = [](const nlohmann::json& asset) {
    GltfBuilder b = validSquare();
    b.doc["asset"] = asset;
    return b;
  };
  EXPECT_EQ(errorOf(withAsset({{"version", "1.0"}})),
            "glTF version 1.0 is not supported (lensrt reads glTF 2.x)");
  EXPECT_EQ(errorOf(withAsset({{"version", "3.0"}})),
            "glTF version 3.0 is not supported (lensrt reads glTF 2.x)");
  EXPECT_EQ(errorOf(withAsset({{"version", "two"}})),
            "asset.version 'two' is not a glTF version (major.minor)");
  EXPECT_EQ(errorOf(withAsset({{"version", "3.0"}, {"minVersion", "2.1"}})),
            "glTF minVersion 2.1 is not supported (lensrt reads glTF 2.0)");
  // Readable as 2.0: a later 2.x, or any version whose minVersion is at most 2.0.
  for (const nlohmann::json& ok : {nlohmann::json{{"version", "2.0"}}, nlohmann::json{{"version", "2.7"}},
                                   nlohmann::json{{"version", "3.0"}, {"minVersion", "2.0"}},
                                   nlohmann::json{{"version", "2.1"}, {"minVersion", "1.0"}}})
    EXPECT_EQ(errorOf(withAsset(ok)), "") << ok.dump();
}

TEST(GltfErrors, DegenerateTrianglesOnly) {
  GltfBuilder b;
  const int pos = b.floats({0, 0, 0, 1, 1, 1, 2, 2, 2, 5, 5, 5}, "VEC3");  // collinear
  b.node({{"mesh", b.mesh({{"attributes", {{"POSITION", pos}}}, {"indices", b.u16({0, 1, 2, 3, 3, 0})}})}});
  EXPECT_EQ(errorOf(b), "nothing to render: all triangles are degenerate");
}

TEST(GltfErrors, NeitherJsonNorGlb) {
  const std::string png = "\x89PNG\r\n\x1a\n rest of an image";
  EXPECT_EQ(
      errorOf(test::writeFile(test::testDir() / "image.gltf", png)),
      "not a glTF file: neither JSON (a .gltf starts with '{') nor binary glTF (a .glb starts with 'glTF')");
  // A byte order mark and white space before the JSON are fine.
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "bom.gltf", "\xEF\xBB\xBF \n" + validSquare().json())),
            "");
}

// A buffer URI naming a FIFO blocked tinygltf forever (its existence check
// opens the file) and one naming a directory read as an absurd size.
TEST(GltfErrors, BufferUriThatIsNotARegularFile) {
  const std::filesystem::path dir = test::testDir();
  const std::filesystem::path fifo = dir / "buffer.fifo";
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const auto& [uri, what] : {std::pair{"buffer.fifo", "a FIFO"}, std::pair{".", "a directory"}}) {
    nlohmann::json doc = nlohmann::json::parse(validSquare().json());
    doc["buffers"][0]["uri"] = uri;
    EXPECT_EQ(errorOf(test::writeFile(dir / "uri.gltf", doc.dump())),
              "URI '" + std::string(uri) + "': " + what + ", not a regular file");
  }
  std::filesystem::remove(fifo);
}

TEST(GltfErrors, GlbWithWrongHeader) {
  std::vector<std::uint8_t> bytes = validSquare().glb();
  bytes[0] = 'x';
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "bad.glb", bytes)),
            "not a binary glTF: the header does not start with 'glTF'");
  bytes[0] = 'g';
  bytes[4] = 1;
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "v1.glb", bytes)),
            "unsupported .glb version 1 (expected 2)");
}

TEST(GltfErrors, TruncatedGlb) {
  std::vector<std::uint8_t> bytes = validSquare().glb();
  const std::size_t full = bytes.size();
  bytes.resize(full - 30);
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "short.glb", bytes)),
            "truncated .glb: the header declares " + std::to_string(full) + " bytes but the file has " +
                std::to_string(full - 30) + " bytes");
  bytes.resize(14);
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "header.glb", bytes)),
            "truncated .glb: the file has 14 bytes, less than the 12-byte header and the JSON chunk header");
}

// The chunk layout of a .glb: little-endian u32 at `offset`.
void putU32(std::vector<std::uint8_t>& bytes, std::size_t offset, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes[offset + i] = static_cast<std::uint8_t>(v >> (8 * i));
}
std::uint32_t getU32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= std::uint32_t{bytes[offset + i]} << (8 * i);
  return v;
}

TEST(GltfErrors, GlbChunksMustFitTheDeclaredLength) {
  const std::vector<std::uint8_t> good = validSquare().glb();
  const std::uint32_t jsonLength = getU32(good, 12);
  const std::size_t binHeader = 20 + jsonLength;
  const std::uint32_t binLength = getU32(good, binHeader);
  ASSERT_EQ(good.size(), binHeader + 8 + binLength);

  // A BIN chunk claiming 8 bytes more than the file holds (tinygltf 2.7 reads past the end).
  std::vector<std::uint8_t> bytes = good;
  putU32(bytes, binHeader, binLength + 8);
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "bin.glb", bytes)),
            "truncated .glb: the BIN chunk declares " + std::to_string(binLength + 8) + " bytes but only " +
                std::to_string(binLength) + " follow it within the declared length");

  bytes = good;
  putU32(bytes, 12, static_cast<std::uint32_t>(good.size()));
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "json.glb", bytes)),
            "broken .glb: the JSON chunk (" + std::to_string(good.size()) +
                " bytes) runs past the declared length of " + std::to_string(good.size()) + " bytes");

  bytes = good;
  putU32(bytes, 16, 0x004E4942);  // BIN where JSON belongs
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "order.glb", bytes)),
            "broken .glb: the first chunk is not the JSON chunk");

  bytes = good;
  putU32(bytes, binHeader + 4, 0x12345678);
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "type.glb", bytes)),
            "broken .glb: the chunk after the JSON chunk is not a BIN chunk");

  // Bytes after the declared length are ignored, as the glTF spec allows readers to.
  bytes = good;
  bytes.insert(bytes.end(), 16, 0);
  EXPECT_EQ(errorOf(test::writeFile(test::testDir() / "trailing.glb", bytes)), "");
}

// Embree aborts on a ray starting beyond 1.8e18; a camera is held to the
// same 1e15 limit as the geometry.
TEST(GltfErrors, CameraBeyondTheCoordinateLimit) {
  GltfBuilder b = validSquare();
  b.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  b.node({{"name", "far"}, {"camera", 0}, {"translation", {0, 0, 2e15}}});
  EXPECT_EQ(errorOf(b), "camera 'far' (node 1) is placed beyond 1e15 (check the node transforms)");
  b.doc["nodes"][1]["translation"] = {0, 0, 5e14};
  EXPECT_EQ(errorOf(b), "");
}

TEST(GltfErrors, SceneIndexOutOfRange) {
  EXPECT_EQ(errorOf(validSquare(), 3), "scene index 3 out of range (the file has 1 scene)");
  // The request is wrong, not the file: the command line makes it a usage error.
  Warnings w;
  EXPECT_THROW(loadGltf(test::writeFile(test::testDir() / "one.gltf", validSquare().json()), 3, w),
               SelectionError);
}

TEST(GltfErrors, UnsupportedRequiredExtension) {
  GltfBuilder b = validSquare();
  b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  EXPECT_EQ(errorOf(b), "required extension KHR_draco_mesh_compression is not supported");
}

TEST(GltfErrors, NodeCycle) {
  GltfBuilder b = validSquare();
  b.doc["nodes"][0]["children"] = {0};
  EXPECT_EQ(errorOf(b), "node 0 is reached twice (a cycle or a shared child; glTF nodes must form trees)");
}

TEST(GltfErrors, NodeAndMeshIndicesOutOfRange) {
  GltfBuilder b = validSquare();
  b.doc["scenes"][0]["nodes"].push_back(7);
  EXPECT_EQ(errorOf(b), "node 7 does not exist");
  GltfBuilder m = validSquare();
  m.doc["nodes"][0]["mesh"] = 3;
  EXPECT_EQ(errorOf(m), "mesh 3 does not exist");
}

// Extension indices are plain JSON numbers: anything but a whole number that
// fits an int is refused by name (4294967295 was converted to int: UB).
TEST(GltfErrors, ExtensionIndicesThatAreNotIndices) {
  for (const double bad : {4294967295.0, -1.0, 0.5}) {
    GltfBuilder b;
    b.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    b.node({{"mesh", b.square()},
            {"extensions", {{"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", bad}}}}}}}});
    std::ostringstream text;
    text.precision(17);
    text << bad;
    EXPECT_EQ(errorOf(b),
              "node 0 EXT_mesh_gpu_instancing TRANSLATION: accessor " + text.str() + " is not an index");
  }
  GltfBuilder l = validSquare();
  l.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  l.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}}};
  l.doc["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 1e300;
  EXPECT_EQ(errorOf(l), "node 0: KHR_lights_punctual light 1.0000000000000001e+300 is not an index");
}

// Random byte corruption of valid files: each either loads or throws
// InputError; any other outcome (a crash, another exception) fails.
void fuzz(const std::vector<std::uint8_t>& original, const std::string& name, unsigned seed) {
  std::mt19937 rng(seed);
  const std::filesystem::path dir = test::testDir();
  for (int round = 0; round < 150; ++round) {
    std::vector<std::uint8_t> bytes = original;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % bytes.size();
      switch (rng() % 3) {
        case 0:
          bytes[at] = static_cast<std::uint8_t>(rng());
          break;
        case 1:
          bytes[at] = static_cast<std::uint8_t>("0123456789-e.,:{}[]\""[rng() % 20]);
          break;
        default:
          bytes.resize(std::max<std::size_t>(at, 1));
      }
    }
    const auto file = test::writeFile(dir / name, bytes);
    Warnings w;
    try {
      loadGltf(file, -1, w);
    } catch (const InputError&) {
    }
  }
}

TEST(GltfErrors, CorruptedFilesNeverCrash) {
  GltfBuilder b;
  b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 0, 0, 1}}}}}};
  const int square = b.square(0);
  b.node({{"mesh", square}, {"translation", {1, 2, 3}}});
  b.node({{"mesh", square}, {"scale", {2, 2, 2}}});
  const std::string text = b.json();
  fuzz(std::vector<std::uint8_t>(text.begin(), text.end()), "fuzz.gltf", 1);
  fuzz(b.glb(), "fuzz.glb", 2);
}

}  // namespace
}  // namespace lensrt
