// Four doubles in an AVX register (GCC/clang vector extensions): the helpers
// the batched optics share (trace_lanes.cpp, exit_pupil.cpp). Callers run them
// only where avx2Enabled() says so, and keep each lane's IEEE operations in the
// scalar code's order (no FMA), so that every lane gives the scalar bits.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define LENSRT_AVX_DOUBLES 1

#include <cstddef>
#include <cstring>
#include <limits>

#define LENSRT_AVX __attribute__((target("avx2")))

namespace lensrt::avx {

using V = double __attribute__((vector_size(32)));
// The all-ones/zero lanes that comparisons of V give.
using M = long long __attribute__((vector_size(32)));
inline constexpr std::size_t kWidth = 4;

LENSRT_AVX inline V splat(double x) {
  return V{x, x, x, x};
}
LENSRT_AVX inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
LENSRT_AVX inline void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
LENSRT_AVX inline M loadMask(const long long* p) {
  M m;
  std::memcpy(&m, p, sizeof m);
  return m;
}
LENSRT_AVX inline void storeMask(long long* p, M m) {
  std::memcpy(p, &m, sizeof m);
}
LENSRT_AVX inline bool none(M m) {
  return (m[0] | m[1] | m[2] | m[3]) == 0;
}
// std::isfinite, lane by lane: |v| <= DBL_MAX (false for NaN).
LENSRT_AVX inline M finite(V v) {
  constexpr long long kNoSign = 0x7fffffffffffffffll;
  return (V)((M)v & M{kNoSign, kNoSign, kNoSign, kNoSign}) <= splat(std::numeric_limits<double>::max());
}
// m ? a : b, lane by lane.
LENSRT_AVX inline V select(M m, V a, V b) {
  return (V)(((M)a & m) | ((M)b & ~m));
}
LENSRT_AVX inline V sqrt(V v) {
  return __builtin_ia32_sqrtpd256(v);
}

}  // namespace lensrt::avx

#endif
