// Which optional instruction sets the hot loops may use. Every SIMD path gives
// the same bits as its scalar twin, so this only changes speed; the tests run
// both ways (LENSRT_DISABLE_AVX=1 holds the scalar paths).
#pragma once

namespace lensrt {

// True when this CPU has AVX2 and the environment does not set
// LENSRT_DISABLE_AVX (checked once per process).
bool avx2Enabled();

}  // namespace lensrt
