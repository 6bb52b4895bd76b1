#include "optics/stop_far_field.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "optics/fft.h"

namespace lensrt {

StopFarField::StopFarField(const std::function<double(double, double)>& stop, int samples, int padding) {
  if (samples < 8 || samples > 1024 || padding < 2 || padding > 16 || samples * padding > 4096)
    throw std::invalid_argument(
        "the stop's far-field table needs 8-1024 samples, padding 2-16, at most 4096^2");
  const int n = samples, m = samples * padding;
  size_ = m;
  cell_ = 1.0 / (2.0 * padding);
  ComplexGrid grid(m);
  // Each sample is the mean amplitude of 4 x 4 points in its cell, so the
  // round edge is not a staircase; the light through the stop is the mean
  // of their intensities (what the sharp edge diffracts beyond the table
  // is the difference).
  constexpr int kSub = 4;
  double light = 0.0;
  const double step = 2.0 / n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double amplitude = 0.0, intensity = 0.0;
      for (int b = 0; b < kSub; ++b)
        for (int a = 0; a < kSub; ++a) {
          const double x = -1.0 + (i + (a + 0.5) / kSub) * step, y = -1.0 + (j + (b + 0.5) / kSub) * step;
          double t = x * x + y * y <= 1.0 ? 1.0 : 0.0;
          if (stop && t > 0.0) t = std::clamp(stop(x, y), 0.0, 1.0);
          amplitude += std::sqrt(t);
          intensity += t;
        }
      grid(i, j) = amplitude / (kSub * kSub);
      light += intensity / (kSub * kSub);
    }
  if (!(light > 0.0)) throw std::invalid_argument("no light passes the stop");
  grid.transform(-1);
  table_.assign(std::size_t(m) * std::size_t(m), 0.0);
  double sum = 0.0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double v = std::norm(grid(i, j));
      table_[std::size_t((j + m / 2) % m) * std::size_t(m) + std::size_t((i + m / 2) % m)] = v;
      sum += v;
    }
  // Parseval: the table's sum is m^2 times the sum of the amplitudes squared.
  captured_ = sum / (double(m) * double(m) * light);
  for (double& v : table_) v /= sum;
  rowCdf_.assign(std::size_t(m) + 1, 0.0);
  cellCdf_.assign(std::size_t(m) * std::size_t(m + 1), 0.0);
  for (int j = 0; j < m; ++j) {
    double row = 0.0;
    double* cdf = &cellCdf_[std::size_t(j) * std::size_t(m + 1)];
    for (int i = 0; i < m; ++i) cdf[i + 1] = row += at(i, j);
    if (row > 0.0)
      for (int i = 1; i <= m; ++i) cdf[i] /= row;
    rowCdf_[std::size_t(j) + 1] = rowCdf_[std::size_t(j)] + row;
  }
}

StopFarField::Sample StopFarField::sample(Vec2d u) const {
  const int m = size_;
  // The row, then the cell in it, each by its cdf; the remainder of u
  // within the chosen interval places the point inside the cell.
  const double target = u.y * rowCdf_.back();
  const int j = std::clamp(
      int(std::upper_bound(rowCdf_.begin(), rowCdf_.end(), target) - rowCdf_.begin()) - 1, 0, m - 1);
  const double rowWidth = rowCdf_[std::size_t(j) + 1] - rowCdf_[std::size_t(j)];
  const double fy =
      rowWidth > 0.0 ? std::clamp((target - rowCdf_[std::size_t(j)]) / rowWidth, 0.0, 1.0) : 0.5;
  const double* cdf = &cellCdf_[std::size_t(j) * std::size_t(m + 1)];
  const int i = std::clamp(int(std::upper_bound(cdf, cdf + m + 1, u.x) - cdf) - 1, 0, m - 1);
  const double cellWidth = cdf[i + 1] - cdf[i];
  const double fx = cellWidth > 0.0 ? std::clamp((u.x - cdf[i]) / cellWidth, 0.0, 1.0) : 0.5;
  Sample s;
  s.frequency = {(i - m / 2 + fx - 0.5) * cell_, (j - m / 2 + fy - 0.5) * cell_};
  s.pdf = at(i, j) / (cell_ * cell_);
  return s;
}

double StopFarField::pdf(Vec2d f) const {
  const int i = int(std::floor(f.x / cell_ + 0.5)) + size_ / 2,
            j = int(std::floor(f.y / cell_ + 0.5)) + size_ / 2;
  if (i < 0 || j < 0 || i >= size_ || j >= size_) return 0.0;
  return at(i, j) / (cell_ * cell_);
}

}  // namespace lensrt
