// The 24 patches of the ColorChecker chart as spectral reflectances: the
// training set of the least-squares fit from a camera's RGB to an output
// space (as pbrt-v4's PixelSensor), and a test chart. BabelColor's average
// of 30 charts, 380-730 nm every 10 nm (data/colorchecker.csv, compiled in).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace lensrt {

inline constexpr std::size_t kColorCheckerPatchCount = 24;

struct ColorCheckerPatch {
  std::string name;                   // "dark-skin", ..., "black-2"
  std::vector<double> wavelengthsNm;  // strictly increasing
  std::vector<double> reflectance;    // 0..1 at each wavelength

  // Linear between samples, 0 outside the measured range (as pbrt-v4).
  double at(double nm) const;
};

// The patches in the chart's order, row by row from the top left (dark skin,
// light skin, ..., the grey scale from white 9.5 to black 2).
const std::array<ColorCheckerPatch, kColorCheckerPatchCount>& colorCheckerPatches();

}  // namespace lensrt
