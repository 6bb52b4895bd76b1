#include "scene/embree_config.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string_view>

#include "core/error.h"

namespace lensrt {
namespace {

enum class Kind { Count, Flag, Verbosity, Isa, Frequency, Name };

struct Key {
  std::string_view name;
  Kind kind;
};

// rtcNewDevice(3) of Embree 3, and the acceleration-structure selections its
// state parser also reads (their values are Embree's to judge).
constexpr std::array kKeys{
    Key{"threads", Kind::Count},
    Key{"user_threads", Kind::Count},
    Key{"set_affinity", Kind::Flag},
    Key{"start_threads", Kind::Flag},
    Key{"isa", Kind::Isa},
    Key{"max_isa", Kind::Isa},
    Key{"hugepages", Kind::Flag},
    Key{"enable_selockmemoryprivilege", Kind::Flag},
    Key{"ignore_config_files", Kind::Flag},
    Key{"verbose", Kind::Verbosity},
    Key{"frequency_level", Kind::Frequency},
    Key{"tri_accel", Kind::Name},
    Key{"tri_accel_mb", Kind::Name},
    Key{"tri_builder", Kind::Name},
    Key{"tri_builder_mb", Kind::Name},
    Key{"tri_traverser", Kind::Name},
    Key{"tri_traverser_mb", Kind::Name},
    Key{"quad_accel", Kind::Name},
    Key{"quad_accel_mb", Kind::Name},
    Key{"quad_builder", Kind::Name},
    Key{"quad_builder_mb", Kind::Name},
    Key{"quad_traverser", Kind::Name},
    Key{"quad_traverser_mb", Kind::Name},
    Key{"instance_accel", Kind::Name},
    Key{"instance_builder", Kind::Name},
};

using namespace std::string_view_literals;
constexpr std::array kIsas{"sse2"sv, "sse4.2"sv, "avx"sv, "avx2"sv, "avx512"sv};
constexpr std::array kFrequencies{"simd128"sv, "simd256"sv, "simd512"sv};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool isCount(std::string_view v, unsigned max) {
  if (v.empty() || v.size() > 6 ||
      !std::all_of(v.begin(), v.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return false;
  return unsigned(std::stoul(std::string(v))) <= max;
}

template <std::size_t N>
std::string joined(const std::array<std::string_view, N>& values) {
  std::string s;
  for (const std::string_view v : values) {
    if (!s.empty()) s += ", ";
    s += v;
  }
  return s;
}

[[noreturn]] void refuse(const std::string& config, const std::string& why) {
  throw UsageError(kEmbreeConfigVariable, why + " in '" + config + "'");
}

}  // namespace

void checkEmbreeConfig(const std::string& config) {
  std::string_view rest = config;
  while (true) {
    const std::size_t comma = rest.find(',');
    const std::string_view entry = trim(rest.substr(0, comma));
    const std::size_t eq = entry.find('=');
    if (eq == std::string_view::npos)
      refuse(config, "expected KEY=VALUE entries separated by commas (e.g. isa=sse4.2,verbose=1), got '" +
                         std::string(entry) + "'");
    const std::string_view key = trim(entry.substr(0, eq)), value = trim(entry.substr(eq + 1));
    const auto it = std::find_if(kKeys.begin(), kKeys.end(), [&](const Key& k) { return k.name == key; });
    if (it == kKeys.end())
      refuse(config, "unknown key '" + std::string(key) +
                         "' (threads, user_threads, set_affinity, start_threads, isa, max_isa, hugepages, "
                         "verbose, frequency_level, or an acceleration-structure key such as tri_accel)");
    bool ok = !value.empty();
    std::string wanted;
    switch (it->kind) {
      case Kind::Count:
        ok = ok && isCount(value, 65536);
        wanted = "a number of threads";
        break;
      case Kind::Flag:
        ok = ok && (value == "0" || value == "1");
        wanted = "0 or 1";
        break;
      case Kind::Verbosity:
        ok = ok && isCount(value, 4);
        wanted = "0 to 4";
        break;
      case Kind::Isa:
        ok = ok && std::find(kIsas.begin(), kIsas.end(), value) != kIsas.end();
        wanted = "one of " + joined(kIsas);
        break;
      case Kind::Frequency:
        ok = ok && std::find(kFrequencies.begin(), kFrequencies.end(), value) != kFrequencies.end();
        wanted = "one of " + joined(kFrequencies);
        break;
      case Kind::Name:
        wanted = "a name";
        break;
    }
    if (!ok) refuse(config, std::string(key) + " takes " + wanted + ", got '" + std::string(value) + "'");
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
}

std::optional<std::string> embreeConfigFromEnvironment() {
  const char* value = std::getenv(kEmbreeConfigVariable);
  if (!value || !*value) return std::nullopt;
  checkEmbreeConfig(value);
  return std::string(value);
}

}  // namespace lensrt
