#include "optics/coating.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace lensrt {

std::optional<Coating> parseCoating(std::string_view name) {
  if (name == "none") return Coating::None;
  if (name == "single") return Coating::Single;
  if (name == "multi") return Coating::Multi;
  return std::nullopt;
}

std::string coatingName(Coating coating) {
  switch (coating) {
    case Coating::Single:
      return "single";
    case Coating::Multi:
      return "multi";
    case Coating::None:
      break;
  }
  return "none";
}

namespace {

// Fresnel amplitude reflection coefficients from medium i into j.
double rs(double ni, double ci, double nj, double cj) {
  return (ni * ci - nj * cj) / (ni * ci + nj * cj);
}
double rp(double ni, double ci, double nj, double cj) {
  return (nj * ci - ni * cj) / (nj * ci + ni * cj);
}

// |r|^2 of a single lossless layer with real interface coefficients r01, r12
// and phase thickness beta: (r01^2 + r12^2 + 2 r01 r12 cos 2b) /
// (1 + r01^2 r12^2 + 2 r01 r12 cos 2b).
double layerReflectance(double r01, double r12, double cos2Beta) {
  const double cross = 2.0 * r01 * r12 * cos2Beta;
  return (r01 * r01 + r12 * r12 + cross) / (1.0 + r01 * r01 * r12 * r12 + cross);
}

}  // namespace

double surfaceTransmittance(Coating coating, double n1, double n2, double cos1, double cos2,
                            double wavelengthNm) {
  if (n1 == n2) return 1.0;
  if (!(cos1 + cos2 > 0.0)) return 0.0;  // grazing on both sides: nothing gets through
  // The transmittance of a lossless interface or stack is the same both
  // ways: work from the lower-index (air) side.
  double n0 = n1, c0 = cos1, ns = n2, cs = cos2;
  if (n0 > ns) std::swap(n0, ns), std::swap(c0, cs);
  const bool glassAir = n0 == 1.0;
  if (coating == Coating::Multi && glassAir) return 1.0 - kMultiLayerReflectance;
  if (coating == Coating::Single && glassAir) {
    // Angle in the layer by Snell's law, and its phase thickness
    // beta = 2 pi n d cos / lambda with d = lambda0 / (4 n).
    const double sin0 = std::sqrt(std::max(0.0, 1.0 - c0 * c0));
    const double sinL = n0 * sin0 / kMgF2Index;
    const double cL = std::sqrt(std::max(0.0, 1.0 - sinL * sinL));
    const double beta =
        2.0 * kPi * kMgF2Index * (kSingleLayerDesignNm / (4.0 * kMgF2Index)) * cL / wavelengthNm;
    const double cos2Beta = std::cos(2.0 * beta);
    const double Rs = layerReflectance(rs(n0, c0, kMgF2Index, cL), rs(kMgF2Index, cL, ns, cs), cos2Beta);
    const double Rp = layerReflectance(rp(n0, c0, kMgF2Index, cL), rp(kMgF2Index, cL, ns, cs), cos2Beta);
    return std::clamp(1.0 - 0.5 * (Rs + Rp), 0.0, 1.0);
  }
  const double s = rs(n0, c0, ns, cs), p = rp(n0, c0, ns, cs);
  return std::clamp(1.0 - 0.5 * (s * s + p * p), 0.0, 1.0);
}

}  // namespace lensrt
