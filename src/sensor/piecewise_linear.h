// Linear interpolation in measured spectra, tabulated at any spacing: 0
// outside the table, where the measurement says nothing (as pbrt-v4's
// piecewise-linear spectra).
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

namespace lensrt {

// The value at `nm` of samples `values` at strictly increasing `wavelengthsNm`
// (the same count); exactly the sample at a tabulated wavelength.
template <class T>
T piecewiseLinear(std::span<const double> wavelengthsNm, std::span<const T> values, double nm) {
  if (wavelengthsNm.empty() || !(nm >= wavelengthsNm.front() && nm <= wavelengthsNm.back())) return T{};
  const auto above = std::upper_bound(wavelengthsNm.begin(), wavelengthsNm.end(), nm);
  if (above == wavelengthsNm.end()) return values.back();
  const std::size_t i = std::size_t(above - wavelengthsNm.begin());  // >= 1: nm >= the first
  const double t = (nm - wavelengthsNm[i - 1]) / (wavelengthsNm[i] - wavelengthsNm[i - 1]);
  return t == 0.0 ? values[i - 1] : values[i - 1] * (1.0 - t) + values[i] * t;
}

}  // namespace lensrt
