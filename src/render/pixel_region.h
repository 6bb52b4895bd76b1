// A rectangle of pixels of the frame (a crop, a tile for a job array, an MPI
// work item): x in [x0, x1), y in [y0, y1), frame coordinates, row 0 at the top.
#pragma once

#include <cstdint>
#include <string>

namespace lensrt {

struct PixelRegion {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;

  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  std::uint64_t pixelCount() const { return std::uint64_t(width()) * std::uint64_t(height()); }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  bool contains(const PixelRegion& r) const { return r.x0 >= x0 && r.x1 <= x1 && r.y0 >= y0 && r.y1 <= y1; }
  bool operator==(const PixelRegion&) const = default;
  // "X0,X1,Y0,Y1", the --crop syntax.
  std::string describe() const;

  static PixelRegion wholeFrame(int width, int height) { return {0, width, 0, height}; }
};

// Tile `index` (from 0) of `count` for `lensrt render --tile I/N`: the frame
// cut into `count` horizontal strips, top to bottom, whose heights differ by
// at most one row (strip i covers rows floor(i*H/N) to floor((i+1)*H/N)).
// Strips keep each part one contiguous block of scanlines. Needs
// 0 <= index < count <= height.
PixelRegion frameStrip(int index, int count, int width, int height);

}  // namespace lensrt
