// Illuminant spectra (relative spectral power) and their colours.
#pragma once

#include <functional>

#include "core/vec.h"

namespace lensrt {

// CIE standard illuminant D65 as tabulated (5 nm, 300-830 nm; 100 at 560 nm).
double d65(double nm);
// The CIE daylight illuminant of a correlated colour temperature,
// S0 + M1 S1 + M2 S2 (CIE 15:2004), 100 at 560 nm. Defined for 4000-25000 K;
// throws std::invalid_argument outside.
double daylightSpectrum(double kelvin, double nm);
// Planck's law, 1 at its peak (Wien's displacement law). kelvin > 0.
double blackbodySpectrum(double kelvin, double nm);

// XYZ of a spectrum: its integral against the CIE 1931 observer over
// 360-830 nm at 1 nm, over kCieYIntegral (an equal-energy 1 has Y = 1).
Vec3d spectrumToXyz(const std::function<double(double)>& spectrum);
// (x, y) chromaticity of XYZ.
Vec2d chromaticity(const Vec3d& xyz);
// The spectrum of a colour temperature as a white balance means it: CIE
// daylight from 4000 K up, a black body below.
double whiteSpectrum(double kelvin, double nm);
// Its XYZ, scaled to Y = 1.
Vec3d whiteXyz(double kelvin);

}  // namespace lensrt
