#include "optics/glass.h"

namespace lensrt {

Dispersion Dispersion::of(const Medium& m) {
  if (m.vd <= 0.0 || m.nd <= 1.0) return {m.nd, 0.0};
  const double dn = (m.nd - 1.0) / m.vd;  // n_F - n_C
  const double inv2 = [](double l) { return 1.0 / (l * l); }(kWavelengthFNm) -
                      [](double l) { return 1.0 / (l * l); }(kWavelengthCNm);
  const double b = dn / inv2;
  return {m.nd - b / (kWavelengthDNm * kWavelengthDNm), b};
}

}  // namespace lensrt
