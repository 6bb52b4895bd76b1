// Invariant checks for the fuzz targets. A broken invariant must stop the run
// loudly in every build (libFuzzer, the sanitizer replay, plain Release), so
// this is not assert(): it prints what failed and aborts.
#pragma once

#include <cstdio>
#include <cstdlib>

#define LENSRT_FUZZ_CHECK(condition)                                                              \
  do {                                                                                            \
    if (!(condition)) {                                                                           \
      std::fprintf(stderr, "%s:%d: fuzz invariant failed: %s\n", __FILE__, __LINE__, #condition); \
      std::abort();                                                                               \
    }                                                                                             \
  } while (false)
