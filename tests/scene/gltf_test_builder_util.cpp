#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "gltf_test_builder.h"

namespace lensrt::test {

const char* const kTwoTexelPngBase64 =
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAAD0lEQVR4nGNoaGhg+A8EABR/BX1DblR6AAAAAElFTkSuQmCC";

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    for (int s = 18; s >= 0; s -= 6) out += table[(v >> s) & 63];
  }
  if (i + 1 == bytes.size()) {
    const std::uint32_t v = bytes[i] << 16;
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8);
    out += table[(v >> 18) & 63];
    out += table[(v >> 12) & 63];
    out += table[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

GltfBuilder::GltfBuilder() {
  doc = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", nlohmann::json::array()}}}}};
}

int GltfBuilder::view(const void* data, std::size_t bytes, std::size_t stride) {
  while (bin.size() % 4) bin.push_back(0);
  const std::size_t offset = bin.size();
  bin.resize(offset + bytes);
  std::memcpy(bin.data() + offset, data, bytes);
  nlohmann::json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}};
  if (stride) v["byteStride"] = stride;
  doc["bufferViews"].push_back(v);
  return static_cast<int>(doc["bufferViews"].size()) - 1;
}

namespace {
int components(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  return 16;
}
int addAccessor(GltfBuilder& b, int view, int componentType, std::size_t values, const std::string& type,
                bool normalized) {
  nlohmann::json a = {{"bufferView", view},
                      {"componentType", componentType},
                      {"count", values / components(type)},
                      {"type", type}};
  if (normalized) a["normalized"] = true;
  b.doc["accessors"].push_back(a);
  return static_cast<int>(b.doc["accessors"].size()) - 1;
}
}  // namespace

int GltfBuilder::floats(const std::vector<float>& v, const std::string& type) {
  return addAccessor(*this, view(v.data(), v.size() * 4), 5126, v.size(), type, false);
}
int GltfBuilder::u16(const std::vector<std::uint16_t>& v, const std::string& type, bool normalized) {
  return addAccessor(*this, view(v.data(), v.size() * 2), 5123, v.size(), type, normalized);
}
int GltfBuilder::u8(const std::vector<std::uint8_t>& v, const std::string& type, bool normalized) {
  return addAccessor(*this, view(v.data(), v.size()), 5121, v.size(), type, normalized);
}
int GltfBuilder::u32(const std::vector<std::uint32_t>& v, const std::string& type) {
  return addAccessor(*this, view(v.data(), v.size() * 4), 5125, v.size(), type, false);
}

int GltfBuilder::mesh(const nlohmann::json& primitive) {
  doc["meshes"].push_back({{"primitives", {primitive}}});
  return static_cast<int>(doc["meshes"].size()) - 1;
}

int GltfBuilder::node(const nlohmann::json& n, bool root) {
  doc["nodes"].push_back(n);
  const int index = static_cast<int>(doc["nodes"].size()) - 1;
  if (root) doc["scenes"][0]["nodes"].push_back(index);
  return index;
}

int GltfBuilder::square(int material) {
  const int pos = floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3");
  const int uv = floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2");
  const int idx = u16({0, 1, 2, 0, 2, 3});
  nlohmann::json prim = {{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"indices", idx}};
  if (material >= 0) prim["material"] = material;
  return mesh(prim);
}

std::string GltfBuilder::json() const {
  nlohmann::json d = doc;
  if (!bin.empty())
    d["buffers"] = {
        {{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
  return d.dump();
}

std::vector<std::uint8_t> GltfBuilder::glb() const {
  nlohmann::json d = doc;
  std::vector<std::uint8_t> body = bin;
  while (body.size() % 4) body.push_back(0);
  if (!bin.empty()) d["buffers"] = {{{"byteLength", bin.size()}}};
  std::string text = d.dump();
  while (text.size() % 4) text += ' ';
  // The magic as the initial contents: inserting it into the empty vector set
  // off GCC 12's false -Wstringop-overflow.
  std::vector<std::uint8_t> out{'g', 'l', 'T', 'F'};
  const auto u32le = [&](std::uint32_t v) {
    for (int s = 0; s < 32; s += 8) out.push_back(static_cast<std::uint8_t>(v >> s));
  };
  const std::size_t total = 12 + 8 + text.size() + (body.empty() ? 0 : 8 + body.size());
  u32le(2);
  u32le(static_cast<std::uint32_t>(total));
  u32le(static_cast<std::uint32_t>(text.size()));
  u32le(0x4E4F534A);  // JSON
  out.insert(out.end(), text.begin(), text.end());
  if (!body.empty()) {
    u32le(static_cast<std::uint32_t>(body.size()));
    u32le(0x004E4942);  // BIN
    out.insert(out.end(), body.begin(), body.end());
  }
  return out;
}

std::filesystem::path testDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "lensrt_scene" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::filesystem::path writeFile(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return path;
}

}  // namespace lensrt::test
