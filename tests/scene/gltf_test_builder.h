// Builds small glTF files for the loader tests: geometry goes into one binary
// buffer, written as a base64 data URI (.gltf) or as the BIN chunk (.glb).
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace lensrt::test {

// A 2x1 RGBA PNG: texel 0 = (128, 128, 128, 0), texel 1 = (255, 255, 255, 255).
extern const char* const kTwoTexelPngBase64;

std::string base64(const std::vector<std::uint8_t>& bytes);

class GltfBuilder {
 public:
  GltfBuilder();

  nlohmann::json doc;  // edit freely; "buffers" is filled in on output
  std::vector<std::uint8_t> bin;

  // Appends bytes (4-byte aligned) and a bufferView over them; returns its index.
  int view(const void* data, std::size_t bytes, std::size_t stride = 0);
  // An accessor over a new view; count defaults to values / components.
  int floats(const std::vector<float>& values, const std::string& type);
  int u16(const std::vector<std::uint16_t>& values, const std::string& type = "SCALAR",
          bool normalized = false);
  int u8(const std::vector<std::uint8_t>& values, const std::string& type = "SCALAR",
         bool normalized = false);
  int u32(const std::vector<std::uint32_t>& values, const std::string& type = "SCALAR");

  // A mesh of one primitive; returns the mesh index.
  int mesh(const nlohmann::json& primitive);
  // A node; returns its index. Also listed as a root of scene 0 when `root`.
  int node(const nlohmann::json& node, bool root = true);
  // Unit square in z = 0 (two CCW triangles seen from +Z), positions + uvs,
  // with optional material; returns the mesh index.
  int square(int material = -1);

  std::string json() const;
  std::vector<std::uint8_t> glb() const;
};

// A fresh directory for one test's files.
std::filesystem::path testDir();
std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text);
std::filesystem::path writeFile(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes);

}  // namespace lensrt::test
