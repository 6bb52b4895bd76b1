// LENSRT_EMBREE_CONFIG, the configuration string lensrt passes to
// rtcNewDevice (e.g. isa=sse4.2, verbose=1): checked before Embree sees it,
// because Embree ignores unknown keys and ISAs silently.
#pragma once

#include <optional>
#include <string>

namespace lensrt {

inline constexpr const char* kEmbreeConfigVariable = "LENSRT_EMBREE_CONFIG";

// The variable's value, or nullopt when it is unset or empty. Throws
// UsageError naming the variable for a malformed entry, an unknown key or a
// value the key cannot take (Embree 3's documented keys, and its
// acceleration-structure keys, whose names Embree itself checks).
std::optional<std::string> embreeConfigFromEnvironment();

// The same check on a given string.
void checkEmbreeConfig(const std::string& config);

}  // namespace lensrt
