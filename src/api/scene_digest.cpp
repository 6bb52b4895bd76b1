#include "api/scene_digest.h"

#include <fmt/core.h>
#include <openssl/evp.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/error.h"
#include "scene/scene_file_access.h"

namespace lensrt {
namespace {

namespace fs = std::filesystem;

std::string readAll(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "cannot read the file to identify the render");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Files a .gltf names by URI (buffers, images), confined as the loader
// confines them; data: URIs are in the file already. A .glb or a file that is
// not JSON contributes itself only: the loader has reported anything wrong
// with it before we get here.
std::vector<SceneFile> referencedFiles(const SceneFileAccess& access, const std::string& text) {
  std::vector<SceneFile> files;
  const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return files;
  for (const char* section : {"buffers", "images"}) {
    const auto it = doc.find(section);
    if (it == doc.end() || !it->is_array()) continue;
    for (const auto& item : *it) {
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) continue;
      if (std::optional<SceneFile> file = access.resolve(uri)) files.push_back(std::move(*file));
    }
  }
  return files;
}

}  // namespace

std::string sceneDigest(const std::string& sceneFile, const std::string& environmentMap,
                        bool allowExternalFiles) {
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
    throw InputError(sceneFile, "OpenSSL cannot compute SHA-256");
  const auto add = [&](const fs::path& file, const std::string& content) {
    const std::string name = file.filename().string() + "\n" + std::to_string(content.size()) + "\n";
    EVP_DigestUpdate(ctx.get(), name.data(), name.size());
    EVP_DigestUpdate(ctx.get(), content.data(), content.size());
  };
  const std::string scene = readAll(sceneFile);
  add(sceneFile, scene);
  const SceneFileAccess access(sceneFile, allowExternalFiles);
  for (const SceneFile& file : referencedFiles(access, scene)) {
    const std::vector<unsigned char> bytes = access.read(file);
    add(file.named, std::string(bytes.begin(), bytes.end()));
  }
  if (!environmentMap.empty()) add(environmentMap, readAll(environmentMap));
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

std::string sha256Hex(std::string_view bytes) {
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("OpenSSL cannot compute SHA-256");
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += fmt::format("{:02x}", digest[i]);
  return hex;
}

}  // namespace lensrt
