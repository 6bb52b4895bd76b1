// The tabulated CIE data (cie_tables.cpp), for color/ alone.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

namespace lensrt::cie {

extern const std::array<double, 471> kX, kY, kZ;  // 1 nm, 360-830 nm
// 5 nm from 300 to 830 nm.
inline constexpr double kTableMinNm = 300, kTableStepNm = 5;
extern const std::array<double, 107> kD65, kDaylightS0, kDaylightS1, kDaylightS2;

// Linear interpolation in a table of values at first, first + step, ...; 0 outside.
template <std::size_t N>
double interpolate(const std::array<double, N>& table, double first, double step, double nm) {
  const double x = (nm - first) / step;
  if (!(x >= 0 && x <= double(N - 1))) return 0;
  const std::size_t i = std::min(std::size_t(x), N - 2);
  const double t = x - double(i);
  return table[i] * (1 - t) + table[i + 1] * t;
}

}  // namespace lensrt::cie
