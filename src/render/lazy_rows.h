// Rows of a lookup table built the first time a lookup needs them, for the
// albedo tables (a lookup interpolates rows i and i + 1, so they come in
// pairs). Thread-safe: once a pair is built, a lookup pays one acquire load.
#pragma once

#include <array>
#include <atomic>
#include <mutex>

namespace lensrt {

// Bilinear lookup in a square table between rows i, i + 1 and columns j,
// j + 1, at fractions s (rows) and t (columns): the albedo tables' lookup.
template <int kN>
float bilerp(const float (&v)[kN][kN], int i, int j, float s, float t) {
  return (v[i][j] * (1 - t) + v[i][j + 1] * t) * (1 - s) + (v[i + 1][j] * (1 - t) + v[i + 1][j + 1] * t) * s;
}

template <int kRows>
class LazyRows {
 public:
  // Makes sure rows i and i + 1 are built, calling build(row) for each row
  // not built yet.
  template <class Build>
  void ensure(int i, const Build& build) const {
    if (!pairReady_[i].load(std::memory_order_acquire)) buildPair(i, build);
  }

 private:
  // Kept out of line so that the lookups stay small.
  template <class Build>
  [[gnu::noinline]] void buildPair(int i, const Build& build) const {
    const std::scoped_lock lock(mutex_);
    for (const int row : {i, i + 1}) {
      if (built_[row]) continue;
      build(row);
      built_[row] = true;
    }
    pairReady_[i].store(true, std::memory_order_release);
  }

  mutable std::mutex mutex_;
  mutable std::array<std::atomic<bool>, kRows - 1> pairReady_{};  // rows i and i + 1 are built
  mutable std::array<bool, kRows> built_{};                       // under mutex_
};

}  // namespace lensrt
