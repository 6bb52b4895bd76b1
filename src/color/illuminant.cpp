#include "color/illuminant.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "color/cie.h"
#include "color/cie_tables.h"

namespace lensrt {

double d65(double nm) {
  return cie::interpolate(cie::kD65, cie::kTableMinNm, cie::kTableStepNm, nm);
}

namespace {

struct DaylightWeights {
  double m1, m2;
};

// CIE 15:2004 section 3.1: the chromaticity x_D of daylight at a CCT, its
// y_D on the daylight locus, and the weights of S1 and S2.
DaylightWeights daylightWeights(double t) {
  if (!(t >= 4000 && t <= 25000))
    throw std::invalid_argument("daylight is defined from 4000 K to 25000 K, not " + std::to_string(t) +
                                " K");
  const double t2 = t * t, t3 = t2 * t;
  const double x = t <= 7000 ? -4.6070e9 / t3 + 2.9678e6 / t2 + 0.09911e3 / t + 0.244063
                             : -2.0064e9 / t3 + 1.9018e6 / t2 + 0.24748e3 / t + 0.237040;
  const double y = -3.000 * x * x + 2.870 * x - 0.275;
  const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
  return {(-1.3515 - 1.7703 * x + 5.9114 * y) / m, (0.0300 - 31.4424 * x + 30.0717 * y) / m};
}

double daylightRaw(const DaylightWeights& w, double nm) {
  const auto at = [nm](const auto& table) {
    return cie::interpolate(table, cie::kTableMinNm, cie::kTableStepNm, nm);
  };
  return at(cie::kDaylightS0) + w.m1 * at(cie::kDaylightS1) + w.m2 * at(cie::kDaylightS2);
}

double planck(double kelvin, double nm) {
  constexpr double c = 299792458.0, h = 6.62606957e-34, kb = 1.3806488e-23;
  const double l = nm * 1e-9;
  return 2 * h * c * c / (std::pow(l, 5) * (std::exp(h * c / (l * kb * kelvin)) - 1));
}

}  // namespace

double daylightSpectrum(double kelvin, double nm) {
  const DaylightWeights w = daylightWeights(kelvin);
  return 100 * daylightRaw(w, nm) / daylightRaw(w, 560);
}

double blackbodySpectrum(double kelvin, double nm) {
  if (!(kelvin > 0)) return 0;
  const double peakNm = 2.8977721e-3 / kelvin * 1e9;
  return planck(kelvin, nm) / planck(kelvin, peakNm);
}

Vec3d spectrumToXyz(const std::function<double(double)>& spectrum) {
  Vec3d xyz{0, 0, 0};
  for (int i = 0; i < int(cie::kX.size()); ++i) {
    const double nm = kCieMinNm + i;
    xyz += cieXyzMatching(nm) * spectrum(nm);
  }
  return xyz / kCieYIntegral;
}

Vec2d chromaticity(const Vec3d& xyz) {
  const double s = xyz.x + xyz.y + xyz.z;
  return s > 0 ? Vec2d{xyz.x / s, xyz.y / s} : Vec2d{0, 0};
}

double whiteSpectrum(double kelvin, double nm) {
  return kelvin >= 4000 ? daylightSpectrum(kelvin, nm) : blackbodySpectrum(kelvin, nm);
}

Vec3d whiteXyz(double kelvin) {
  const Vec3d xyz = spectrumToXyz([kelvin](double nm) { return whiteSpectrum(kelvin, nm); });
  return xyz / xyz.y;
}

}  // namespace lensrt
