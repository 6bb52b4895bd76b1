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

// The same helpers on eight doubles in an AVX-512 register (F for the
// arithmetic, DQ for comparisons as lane masks); callers run them only where
// avx512Enabled() says so. The same operations per lane as the four-wide
// ones, so the same bits: AVX-512 brings FMA, which a compiler would
// contract a * b + c into (one rounding instead of two), so a file that calls
// them is compiled with -ffp-contract=off (src/optics/CMakeLists.txt: GCC's
// optimize attribute would do it here, but clang ignores it, with a warning).
#define LENSRT_AVX512 __attribute__((target("avx512f,avx512dq")))

namespace lensrt::avx512 {

using V = double __attribute__((vector_size(64)));
using M = long long __attribute__((vector_size(64)));
inline constexpr std::size_t kWidth = 8;

LENSRT_AVX512 inline V splat(double x) {
  return V{x, x, x, x, x, x, x, x};
}
LENSRT_AVX512 inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
LENSRT_AVX512 inline void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
LENSRT_AVX512 inline M loadMask(const long long* p) {
  M m;
  std::memcpy(&m, p, sizeof m);
  return m;
}
LENSRT_AVX512 inline void storeMask(long long* p, M m) {
  std::memcpy(p, &m, sizeof m);
}
LENSRT_AVX512 inline bool none(M m) {
  return (m[0] | m[1] | m[2] | m[3] | m[4] | m[5] | m[6] | m[7]) == 0;
}
LENSRT_AVX512 inline M finite(V v) {
  constexpr long long kNoSign = 0x7fffffffffffffffll;
  return (V)((M)v & M{kNoSign, kNoSign, kNoSign, kNoSign, kNoSign, kNoSign, kNoSign, kNoSign}) <=
         splat(std::numeric_limits<double>::max());
}
LENSRT_AVX512 inline V select(M m, V a, V b) {
  return (V)(((M)a & m) | ((M)b & ~m));
}
// Rounded as the current mode says, as the 4-wide one (_MM_FROUND_CUR_DIRECTION: 4).
LENSRT_AVX512 inline V sqrt(V v) {
#if defined(__clang__)
  return __builtin_ia32_sqrtpd512(v, 4);
#else
  return __builtin_ia32_sqrtpd512_mask(v, v, 0xff, 4);
#endif
}

}  // namespace lensrt::avx512

#endif
