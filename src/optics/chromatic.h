// Chromatic aberration of a prescription from its glasses' dispersion
// (glass.h): axial colour (the focus moves with wavelength) and lateral
// colour (the image height of an off-axis point does).
#pragma once

#include <optional>
#include <vector>

#include "optics/glass.h"
#include "optics/lens_system.h"
#include "optics/prescription.h"

namespace lensrt {

// True when any medium has dispersion data (V_d or Sellmeier coefficients).
bool hasDispersion(const LensPrescription& lens);

// The prescription with every medium's n_d replaced by its index at
// `wavelengthNm`, so the paraxial analysis (which reads n_d) runs at that
// wavelength.
LensPrescription atWavelength(const LensPrescription& lens, double wavelengthNm);

// Paraxial back focal length at the C line minus that at the F line, mm
// (positive: red focuses behind blue, an undercorrected lens).
double axialColorMm(const LensPrescription& lens);

// Lateral colour at an image height: the field angle whose d-line chief ray
// lands at `imageHeightMm` on the infinity-focus film plane (the d line's
// paraxial rear focal plane), and the exact chief rays at the F and C lines on
// that plane. nullopt when no chief ray reaches that height.
struct LateralColor {
  double fieldAngleDeg = 0.0;
  double heightFMm = 0.0;  // magnitudes of the image heights
  double heightCMm = 0.0;
  double um() const { return (heightFMm - heightCMm) * 1000.0; }  // F minus C
};
std::optional<LateralColor> lateralColor(const LensSystem& lens, double imageHeightMm);

// Curves for `lens plot --what chromatic`, `points` each: the paraxial focal
// shift (BFL at a wavelength minus at the d line) from 400 to 700 nm, and
// lateral colour (F minus C, um; NaN where no chief ray reaches) against the
// d-line image height from 0 to `maxImageHeightMm`, object at infinity.
struct ChromaticCurves {
  std::vector<double> wavelengthNm, focalShiftMm;
  std::vector<double> imageHeightMm, lateralColorUm;
};
ChromaticCurves chromaticCurves(const LensSystem& lens, double maxImageHeightMm, int points = 41);

// The paraxial focal length against wavelength, as a ratio to the d line's,
// for the thin and thick lens models derived from a lens: tabulated every
// 5 nm from 380 to 780 nm and interpolated linearly (the curve is smooth).
class FocalLengthRatio {
 public:
  explicit FocalLengthRatio(const LensPrescription& lens);
  double at(double wavelengthNm) const;

 private:
  static constexpr double kMinNm = 380.0, kStepNm = 5.0;
  std::vector<double> ratio_;
};

}  // namespace lensrt
