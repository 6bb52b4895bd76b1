// Safe lookups in tinygltf's JSON-like Value (its own Get() asserts on misuse).
#pragma once

#include <tiny_gltf.h>

#include <optional>
#include <string>

namespace lensrt::gltf {

inline const tinygltf::Value* member(const tinygltf::Value& v, const std::string& key) {
  if (!v.IsObject() || !v.Has(key)) return nullptr;
  return &v.Get(key);
}

inline std::optional<double> numberMember(const tinygltf::Value& v, const std::string& key) {
  const tinygltf::Value* m = member(v, key);
  if (!m || !m->IsNumber()) return std::nullopt;
  return m->GetNumberAsDouble();
}

inline const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const std::string& name) {
  const auto it = extensions.find(name);
  return it == extensions.end() ? nullptr : &it->second;
}

}  // namespace lensrt::gltf
