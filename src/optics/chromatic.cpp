#include "optics/chromatic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "optics/distortion.h"
#include "optics/paraxial.h"

namespace lensrt {

bool hasDispersion(const LensPrescription& lens) {
  // Whatever the model (Abbe number or Sellmeier coefficients): an index
  // that differs between the F and C lines.
  for (const Surface& s : lens.surfaces) {
    const Dispersion d = Dispersion::of(s.medium);
    if (d.index(kWavelengthFNm) != d.index(kWavelengthCNm)) return true;
  }
  return false;
}

LensPrescription atWavelength(const LensPrescription& lens, double wavelengthNm) {
  LensPrescription out = lens;
  for (Surface& s : out.surfaces) s.medium.nd = Dispersion::of(s.medium).index(wavelengthNm);
  return out;
}

double axialColorMm(const LensPrescription& lens) {
  return computeParaxial(atWavelength(lens, kWavelengthCNm)).bfl -
         computeParaxial(atWavelength(lens, kWavelengthFNm)).bfl;
}

std::optional<LateralColor> lateralColor(const LensSystem& lens, double imageHeightMm) {
  const double film = lens.paraxial().bfl;
  const std::optional<double> angle = fieldAngleForImageHeight(lens, kInfinity, film, imageHeightMm);
  if (!angle) return std::nullopt;
  const FieldPoint field{*angle, kInfinity};
  const std::optional<double> f = chiefRayImageHeight(lens, field, film, kWavelengthFNm);
  const std::optional<double> c = chiefRayImageHeight(lens, field, film, kWavelengthCNm);
  if (!f || !c) return std::nullopt;
  return LateralColor{*angle, std::abs(*f), std::abs(*c)};
}

ChromaticCurves chromaticCurves(const LensSystem& lens, double maxImageHeightMm, int points) {
  ChromaticCurves out;
  const double bflD = lens.paraxial().bfl;
  for (int i = 0; i < points; ++i) {
    const double wl = 400.0 + 300.0 * i / (points - 1);
    out.wavelengthNm.push_back(wl);
    out.focalShiftMm.push_back(computeParaxial(atWavelength(lens.prescription(), wl)).bfl - bflD);
  }
  for (int i = 0; i < points; ++i) {
    const double h = maxImageHeightMm * i / (points - 1);
    // On the axis both chief rays run along it: no lateral colour.
    const std::optional<LateralColor> lc = i == 0 ? LateralColor{} : lateralColor(lens, h);
    out.imageHeightMm.push_back(h);
    out.lateralColorUm.push_back(lc ? lc->um() : std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

FocalLengthRatio::FocalLengthRatio(const LensPrescription& lens) {
  const double efl = computeParaxial(lens).efl;
  for (double wl = kMinNm; wl <= 780.0 + 1e-9; wl += kStepNm)
    ratio_.push_back(computeParaxial(atWavelength(lens, wl)).efl / efl);
}

double FocalLengthRatio::at(double wavelengthNm) const {
  const double x = std::clamp((wavelengthNm - kMinNm) / kStepNm, 0.0, double(ratio_.size() - 1));
  const std::size_t i = std::min(std::size_t(x), ratio_.size() - 2);
  const double t = x - double(i);
  return ratio_[i] + t * (ratio_[i + 1] - ratio_[i]);
}

}  // namespace lensrt
