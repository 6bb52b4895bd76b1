// Which optional instruction sets the hot loops may use. Every SIMD path gives
// the same bits as its scalar twin, so this only changes speed; the tests run
// both ways (LENSRT_DISABLE_AVX=1 holds the scalar paths).
#pragma once

namespace lensrt {

// True when this CPU has AVX2 and the environment does not set
// LENSRT_DISABLE_AVX (checked once per process).
bool avx2Enabled();
// True when avx2Enabled() and the CPU has AVX-512 F and DQ, unless the
// environment sets LENSRT_DISABLE_AVX512 (which holds the AVX2 paths, for
// the tests). The 8-wide paths give the bits of the 4-wide ones.
bool avx512Enabled();

}  // namespace lensrt
