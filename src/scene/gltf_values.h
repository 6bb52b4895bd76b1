// Safe lookups in tinygltf's JSON-like Value (its own Get() asserts on misuse).
#pragma once

#include <tiny_gltf.h>

#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
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

// An index written as a JSON number in an extension (tinygltf checks the
// core schema's indices, not these): a whole number that fits an int.
inline bool isIndex(double v) {
  return v >= 0.0 && v <= double(std::numeric_limits<int>::max()) && v == std::floor(v);
}

// A number as the user wrote it, for messages (4294967295, 1.5, -1).
inline std::string numberText(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

inline const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const std::string& name) {
  const auto it = extensions.find(name);
  return it == extensions.end() ? nullptr : &it->second;
}

}  // namespace lensrt::gltf
