// Discrete and piecewise-constant distributions for importance sampling
// lights and environment maps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec.h"

namespace lensrt {

// Picks index i with probability w_i / sum(w). Negative or non-finite weights
// count as zero.
class Distribution1D {
 public:
  Distribution1D() = default;
  explicit Distribution1D(const std::vector<float>& weights);

  std::size_t size() const { return weights_.size(); }
  double total() const { return total_; }
  bool empty() const { return !(total_ > 0); }
  // Index for u in [0,1); `remapped` receives u rescaled to [0,1) within the bin.
  std::size_t sample(float u, float* remapped = nullptr) const;
  float probability(std::size_t i) const { return empty() ? 0.0f : float(weights_[i] / total_); }

 private:
  std::vector<double> weights_;
  std::vector<double> cdf_;  // size + 1, cdf_[0] = 0, normalised
  double total_ = 0;
  // Guide table (the cutpoint method): guide_[b] is where the search for
  // u = b / K ends, K = guide_.size() - 1 a power of two, so a u in
  // [b / K, (b + 1) / K) is searched for between guide_[b] and guide_[b + 1]
  // only: the same bin as a search of the whole cdf, in a step or two.
  std::vector<std::uint32_t> guide_;
};

// Piecewise-constant density over [0,1)^2 on a width x height grid (row-major).
class Distribution2D {
 public:
  Distribution2D() = default;
  Distribution2D(const std::vector<float>& weights, int width, int height);

  bool empty() const { return marginal_.empty(); }
  // Point in [0,1)^2 and its density with respect to area in [0,1)^2.
  Vec2f sample(const Vec2f& u, float* pdf) const;
  float pdf(const Vec2f& p) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<Distribution1D> rows_;
  Distribution1D marginal_;
};

}  // namespace lensrt
