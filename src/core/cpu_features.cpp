#include "core/cpu_features.h"

#include <cstdlib>

namespace lensrt {

bool avx2Enabled() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  static const bool enabled = __builtin_cpu_supports("avx2") && !std::getenv("LENSRT_DISABLE_AVX");
  return enabled;
#else
  return false;
#endif
}

bool avx512Enabled() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  static const bool enabled = avx2Enabled() && __builtin_cpu_supports("avx512f") &&
                              __builtin_cpu_supports("avx512dq") && !std::getenv("LENSRT_DISABLE_AVX512");
  return enabled;
#else
  return false;
#endif
}

}  // namespace lensrt
