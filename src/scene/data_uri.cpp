#include "scene/data_uri.h"

#include <array>
#include <cstdint>

namespace lensrt::gltf {
namespace {

// Value of each base64 character; -1 for others.
constexpr std::array<std::int8_t, 256> kValues = [] {
  std::array<std::int8_t, 256> v{};
  v.fill(-1);
  constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (std::size_t i = 0; i < kAlphabet.size(); ++i)
    v[static_cast<unsigned char>(kAlphabet[i])] = std::int8_t(i);
  return v;
}();

}  // namespace

std::optional<std::string> decodeBase64DataUri(std::string_view uri) {
  const std::size_t comma = uri.find(',');
  if (!uri.starts_with("data:") || comma == std::string_view::npos) return std::nullopt;
  if (!uri.substr(0, comma).ends_with(";base64")) return std::nullopt;
  std::string_view data = uri.substr(comma + 1);
  while (data.ends_with('=')) data.remove_suffix(1);
  if (uri.size() - comma - 1 - data.size() > 2 || data.size() % 4 == 1) return std::nullopt;
  std::string out;
  out.reserve(data.size() / 4 * 3 + 2);
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : data) {
    const int v = kValues[static_cast<unsigned char>(c)];
    if (v < 0) return std::nullopt;
    bits = (bits << 6) | std::uint32_t(v);
    if (++count == 4) {
      out.push_back(char(bits >> 16));
      out.push_back(char(bits >> 8));
      out.push_back(char(bits));
      bits = 0;
      count = 0;
    }
  }
  if (count == 2) out.push_back(char(bits >> 4));
  if (count == 3) {
    out.push_back(char(bits >> 10));
    out.push_back(char(bits >> 2));
  }
  return out;
}

}  // namespace lensrt::gltf
