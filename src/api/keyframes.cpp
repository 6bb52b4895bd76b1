#include "api/keyframes.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace lensrt {

bool isKeyframes(const std::string& text) {
  return text.find(':') != std::string::npos;
}

Keyframes parseKeyframes(const std::string& flag, const std::string& text, bool (*valid)(double),
                         const std::string& expected) {
  Keyframes keys;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::size_t colon = item.find(':');
    char* e1 = nullptr;
    char* e2 = nullptr;
    const double t = colon == std::string::npos ? 0.0 : std::strtod(item.c_str(), &e1);
    const double v = colon == std::string::npos ? 0.0 : std::strtod(item.c_str() + colon + 1, &e2);
    if (colon == std::string::npos || colon == 0 || e1 != item.c_str() + colon || colon + 1 == item.size() ||
        *e2 != '\0' || !std::isfinite(t))
      throw UsageError(flag,
                       fmt::format("expected keyframes SECONDS:{},SECONDS:{},... (e.g. 0:1.2,2:4), got '{}'",
                                   expected, expected, text));
    if (!valid(v)) throw UsageError(flag, fmt::format("keyframe '{}': expected {}", item, expected));
    if (!keys.empty() && !(t > keys.back().first))
      throw UsageError(flag, fmt::format("keyframe times must increase, got '{}'", text));
    keys.emplace_back(t, v);
    start = end + 1;
  }
  return keys;
}

double valueAt(const Keyframes& keys, double seconds) {
  if (seconds <= keys.front().first) return keys.front().second;
  for (std::size_t k = 1; k < keys.size(); ++k)
    if (seconds < keys[k].first) {
      const double u = (seconds - keys[k - 1].first) / (keys[k].first - keys[k - 1].first);
      return keys[k - 1].second + u * (keys[k].second - keys[k - 1].second);
    }
  return keys.back().second;
}

}  // namespace lensrt
