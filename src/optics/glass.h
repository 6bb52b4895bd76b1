// Optical media: refractive index as a function of wavelength.
//
// Two models. When a medium carries Sellmeier coefficients (a catalogue glass,
// a Zemax file, a JSON lens that gives them) the index is the Schott/Sellmeier
// form n^2 - 1 = sum B_i l^2 / (l^2 - C_i), l in micrometres, shifted by the
// (tiny, < 2e-4) constant that makes it give n_d exactly at the d line, so the
// d line traces identically whichever model a glass has. Otherwise it is a
// two-term Cauchy fit n(l) = A + B / l^2 through n(587.56 nm) = n_d and
// n_F - n_C = (n_d - 1) / V_d: exact at the d line, a smooth, physically
// sensible estimate elsewhere (within ~1e-3 of Sellmeier across 400-700 nm for
// ordinary crowns and flints).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace lensrt {

inline constexpr double kWavelengthDNm = 587.5618;  // helium d line
inline constexpr double kWavelengthFNm = 486.1327;  // hydrogen F line
inline constexpr double kWavelengthCNm = 656.2725;  // hydrogen C line

// Sellmeier coefficients in the Schott form (C in square micrometres).
struct Sellmeier {
  std::array<double, 3> b{};
  std::array<double, 3> c{};  // um^2

  // The index the formula itself gives (no d-line shift).
  double index(double wavelengthNm) const;
  bool operator==(const Sellmeier&) const = default;
};

// The medium after a surface. Air is n_d = 1 with no dispersion (V_d = 0).
struct Medium {
  double nd = 1.0;
  double vd = 0.0;    // 0: no dispersion data (index is n_d at every wavelength)
  std::string glass;  // catalogue name when known, e.g. "SK16"; empty otherwise
  // When present, the index away from the d line follows these, not V_d.
  std::optional<Sellmeier> sellmeier;

  bool isAir() const { return nd == 1.0; }
};

// Why Sellmeier coefficients cannot describe a glass in the visible (their
// index is not finite and within [1, 4] over 350-900 nm, or a pole of the
// formula falls there); empty when they are fine. Readers report it.
std::string sellmeierProblem(const Sellmeier& s);

// The index of a medium at any wavelength, precomputed once for fast tracing:
// index() is a multiply-add for Cauchy media and three divisions and a square
// root for Sellmeier ones. Callers that trace at the d line use n_d directly.
struct Dispersion {
  // Cauchy form (also the fallback when there is no Sellmeier data).
  double a = 1.0;  // n at infinite wavelength
  double b = 0.0;  // nm^2
  // Sellmeier form, when `sellmeier` is true: B_i, C_i in nm^2, and the shift
  // that makes index(d line) == n_d exactly.
  bool sellmeier = false;
  std::array<double, 3> sb{};
  std::array<double, 3> sc{};  // nm^2
  double shift = 0.0;

  static Dispersion of(const Medium& m);
  double index(double wavelengthNm) const {
    if (!sellmeier) return a + b / (wavelengthNm * wavelengthNm);
    const double l2 = wavelengthNm * wavelengthNm;
    return shift +
           std::sqrt(1.0 + sb[0] * l2 / (l2 - sc[0]) + sb[1] * l2 / (l2 - sc[1]) + sb[2] * l2 / (l2 - sc[2]));
  }
};

}  // namespace lensrt
