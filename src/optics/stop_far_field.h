// The Fraunhofer far field of the aperture stop, tabulated and importance-
// sampled: the library piece a diffraction render (issue 37's
// `--diffraction on`, not wired) needs to bend each camera ray where it
// crosses the stop.
//
// The stop's amplitude transmittance t(x, y) (x, y in units of the stop's
// radius a) diffracts a ray into directions whose direction cosines change
// by (lambda / a) (fx, fy) with density |T(fx, fy)|^2, T the Fourier
// transform of t and f in cycles per stop radius. The table is |T|^2 by FFT
// of t sampled on `samples` x `samples` points over [-1, 1]^2, padded
// `padding` times: cells of 1 / (2 padding) cycles per radius, out to
// +-samples / 4. The light beyond (a sharp edge's far tail) is left out;
// `capturedLight()` says how much the table holds.
#pragma once

#include <functional>
#include <vector>

#include "core/vec.h"

namespace lensrt {

class StopFarField {
 public:
  // `stop`: the intensity transmittance at (x, y) in stop radii, in [0, 1]
  // (its square root is the amplitude); empty: the round stop. Throws
  // std::invalid_argument when nothing passes or the sizes are out of range
  // (samples 8-1024, padding 2-16, the table at most 4096^2).
  explicit StopFarField(const std::function<double(double, double)>& stop = {}, int samples = 64,
                        int padding = 8);

  struct Sample {
    Vec2d frequency;   // cycles per stop radius
    double pdf = 0.0;  // per unit of frequency area
  };
  // A frequency drawn in proportion to the table (a cell by its share, then
  // uniform inside it) from u in [0, 1)^2.
  Sample sample(Vec2d u) const;
  double pdf(Vec2d frequency) const;

  int size() const { return size_; }
  double cellSize() const { return cell_; }  // cycles per stop radius
  // The table's value at cell (i, j), frequency ((i - size/2) cell, (j - size/2) cell); sums to 1.
  double at(int i, int j) const { return table_[std::size_t(j) * std::size_t(size_) + std::size_t(i)]; }
  // The fraction of the light through the stop that the table holds.
  double capturedLight() const { return captured_; }

 private:
  int size_ = 0;
  double cell_ = 0.0;
  double captured_ = 0.0;
  std::vector<double> table_;    // normalised, row by row
  std::vector<double> rowCdf_;   // size + 1: cumulative row sums
  std::vector<double> cellCdf_;  // size x (size + 1): cumulative within each row, normalised per row
};

}  // namespace lensrt
