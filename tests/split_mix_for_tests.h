// A small, fast and reproducible stream of uniform doubles in [0, 1) for the
// stochastic traces' tests (SplitMix64: Steele, Lea and Flood 2014).
#pragma once

#include <cstdint>

namespace lensrt::test {

struct SplitMix {
  std::uint64_t state;
  double operator()() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
};

}  // namespace lensrt::test
