#include "optics/glass.h"

#include <cmath>
#include <cstdio>

namespace lensrt {

double Sellmeier::index(double wavelengthNm) const {
  const double l2 = wavelengthNm * wavelengthNm * 1e-6;  // um^2
  double n2 = 1.0;
  for (int i = 0; i < 3; ++i) n2 += b[i] * l2 / (l2 - c[i]);
  return std::sqrt(n2);
}

std::string sellmeierProblem(const Sellmeier& s) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(s.b[i]) || !std::isfinite(s.c[i]) || std::abs(s.b[i]) > 1e3 || std::abs(s.c[i]) > 1e6)
      return "Sellmeier coefficients must be finite and of sensible size";
    // A pole (l^2 = C) inside or near the visible would make the index jump.
    if (s.c[i] > 0.30 * 0.30 && s.c[i] < 0.95 * 0.95) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "Sellmeier C%d = %g um^2 puts a pole at %.0f nm, inside 300-950 nm",
                    i + 1, s.c[i], 1000.0 * std::sqrt(s.c[i]));
      return buf;
    }
  }
  for (double l = 350.0; l <= 900.0; l += 5.0) {
    const double n = s.index(l);
    if (!(n >= 1.0 && n <= 4.0)) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "Sellmeier index at %.0f nm is %g, outside [1, 4]", l, n);
      return buf;
    }
  }
  return {};
}

Dispersion Dispersion::of(const Medium& m) {
  if (m.sellmeier && m.nd > 1.0) {
    Dispersion d;
    d.sellmeier = true;
    for (int i = 0; i < 3; ++i) {
      d.sb[i] = m.sellmeier->b[i];
      d.sc[i] = m.sellmeier->c[i] * 1e6;  // um^2 -> nm^2
    }
    d.shift = m.nd - m.sellmeier->index(kWavelengthDNm);
    // The Cauchy pair stays meaningful (n_d and the Sellmeier n_F - n_C) for
    // callers that want a cheap approximation.
    const double dn = m.sellmeier->index(kWavelengthFNm) - m.sellmeier->index(kWavelengthCNm);
    const double inv2 = 1.0 / (kWavelengthFNm * kWavelengthFNm) - 1.0 / (kWavelengthCNm * kWavelengthCNm);
    d.b = dn / inv2;
    d.a = m.nd - d.b / (kWavelengthDNm * kWavelengthDNm);
    return d;
  }
  if (m.vd <= 0.0 || m.nd <= 1.0) return {m.nd, 0.0};  // air, or no dispersion data
  const double dn = (m.nd - 1.0) / m.vd;               // n_F - n_C
  const double inv2 = [](double l) { return 1.0 / (l * l); }(kWavelengthFNm) -
                      [](double l) { return 1.0 / (l * l); }(kWavelengthCNm);
  const double b = dn / inv2;
  return {m.nd - b / (kWavelengthDNm * kWavelengthDNm), b};
}

}  // namespace lensrt
