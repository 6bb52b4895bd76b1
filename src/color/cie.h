// The CIE 1931 2-degree standard observer: the colour matching functions
// xbar, ybar, zbar, tabulated at 1 nm from 360 to 830 nm (CIE 018:2019).
#pragma once

#include "core/vec.h"

namespace lensrt {

inline constexpr double kCieMinNm = 360, kCieMaxNm = 830;
// The sum of ybar over the 1 nm table: a spectrum's Y is its integral
// against ybar over this (so the equal-energy spectrum 1 has Y = 1).
inline constexpr double kCieYIntegral = 106.856895;

// (xbar, ybar, zbar) at a wavelength, interpolated linearly; 0 outside.
Vec3d cieXyzMatching(double nm);

}  // namespace lensrt
