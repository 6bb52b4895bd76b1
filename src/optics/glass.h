// Optical media: refractive index from n_d and the Abbe number V_d.
// Dispersion is modelled by a two-term Cauchy fit n(l) = A + B / l^2 through
// n(587.56 nm) = n_d and n_F - n_C = (n_d - 1) / V_d, so the d line gives n_d
// exactly and other wavelengths are a smooth, physically sensible estimate.
#pragma once

#include <string>

namespace lensrt {

inline constexpr double kWavelengthDNm = 587.5618;  // helium d line
inline constexpr double kWavelengthFNm = 486.1327;  // hydrogen F line
inline constexpr double kWavelengthCNm = 656.2725;  // hydrogen C line

// The medium after a surface. Air is n_d = 1 with no dispersion (V_d = 0).
struct Medium {
  double nd = 1.0;
  double vd = 0.0;    // 0: no dispersion data (index is n_d at every wavelength)
  std::string glass;  // catalogue name when known, e.g. "SK16"; empty otherwise

  bool isAir() const { return nd == 1.0; }
};

// Cauchy coefficients of a medium, precomputed once for fast tracing.
struct Dispersion {
  double a = 1.0;  // n at infinite wavelength
  double b = 0.0;  // nm^2
  static Dispersion of(const Medium& m);
  double index(double wavelengthNm) const { return a + b / (wavelengthNm * wavelengthNm); }
};

}  // namespace lensrt
