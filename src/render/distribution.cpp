#include "render/distribution.h"

#include <algorithm>
#include <cmath>

namespace lensrt {

Distribution1D::Distribution1D(const std::vector<float>& weights)
    : weights_(weights.size()), cdf_(weights.size() + 1) {
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const double w = weights[i];
    weights_[i] = std::isfinite(w) && w > 0 ? w : 0.0;
    cdf_[i + 1] = cdf_[i] + weights_[i];
  }
  total_ = cdf_.back();
  if (total_ > 0)
    for (double& c : cdf_) c /= total_;
  // Few bins: a plain search is as quick.
  if (weights_.size() < 8 || weights_.size() >= (std::size_t{1} << 31) || !(total_ > 0) ||
      !std::isfinite(total_))
    return;
  std::size_t k = 1;
  while (k < weights_.size() && k < (std::size_t{1} << 16)) k *= 2;
  guide_.resize(k + 1);
  for (std::size_t b = 0; b <= k; ++b)
    guide_[b] =
        std::uint32_t(std::upper_bound(cdf_.begin() + 1, cdf_.end(), double(b) / double(k)) - cdf_.begin());
}

std::size_t Distribution1D::sample(float u, float* remapped) const {
  // First bin whose upper cdf exceeds u; zero-weight bins are never chosen.
  const double x = u;
  auto it = cdf_.end();
  if (!guide_.empty() && x >= 0 && x < 1) {
    // K is a power of two: x * K and b / K are exact, so b / K <= x < (b + 1) / K.
    const std::size_t k = guide_.size() - 1, b = std::size_t(x * double(k));
    it = std::upper_bound(cdf_.begin() + guide_[b], cdf_.begin() + guide_[b + 1], x);
  } else {
    it = std::upper_bound(cdf_.begin() + 1, cdf_.end(), x);
  }
  std::size_t i = std::min<std::size_t>(std::size_t(it - cdf_.begin()) - 1, weights_.size() - 1);
  while (weights_[i] == 0 && i > 0) --i;  // u landed exactly on the top of the cdf
  if (remapped) {
    const double width = cdf_[i + 1] - cdf_[i];
    const double r = width > 0 ? (double(u) - cdf_[i]) / width : 0.0;
    *remapped = float(std::clamp(r, 0.0, double(std::nextafter(1.0f, 0.0f))));
  }
  return i;
}

Distribution2D::Distribution2D(const std::vector<float>& weights, int width, int height)
    : width_(width), height_(height) {
  std::vector<float> rowTotals(height);
  rows_.reserve(height);
  for (int y = 0; y < height; ++y) {
    std::vector<float> row(weights.begin() + std::size_t(y) * width,
                           weights.begin() + std::size_t(y + 1) * width);
    rows_.emplace_back(row);
    rowTotals[y] = float(rows_.back().total());
  }
  marginal_ = Distribution1D(rowTotals);
  if (marginal_.empty()) rows_.clear();
}

Vec2f Distribution2D::sample(const Vec2f& u, float* pdf) const {
  float uy = 0, ux = 0;
  const std::size_t y = marginal_.sample(u.y, &uy);
  const std::size_t x = rows_[y].sample(u.x, &ux);
  if (pdf) *pdf = marginal_.probability(y) * rows_[y].probability(x) * float(width_) * float(height_);
  return {(float(x) + ux) / float(width_), (float(y) + uy) / float(height_)};
}

float Distribution2D::pdf(const Vec2f& p) const {
  if (marginal_.empty()) return 0;
  const int x = std::clamp(int(p.x * float(width_)), 0, width_ - 1);
  const int y = std::clamp(int(p.y * float(height_)), 0, height_ - 1);
  return marginal_.probability(y) * rows_[y].probability(x) * float(width_) * float(height_);
}

}  // namespace lensrt
