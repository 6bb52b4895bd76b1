// Set-up shared by `lens psf`, `lens mtf` and Lens.psf() / Lens.mtf(): the
// lens stopped down and focused (api/lens_view.h), the stop's shape (blades
// or a grey mask, as the full-lens camera cuts it) and the PSF model of one
// field point (optics/psf.h).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "api/lens_view.h"
#include "optics/psf.h"

namespace lensrt {

struct LensWaveOptions {
  double fieldDeg = 0.0;  // from the axis, object side, toward +x
  // Empty: the d, F and C lines, equal weights.
  std::vector<double> wavelengthsNm;
  std::vector<double> weights;  // empty: equal
  int pupilSamples = 0;         // 0: automatic
  int padding = 4;
  int blades = 0;  // 0: round; else >= 3, a polygon of the f-number's area (as `render --blades`)
  double bladeRotationDeg = 0.0;
  std::string apertureMask;  // a grey-scale image over the stop (as `render --aperture-mask`)
};

struct LensWave {
  LensView view;
  std::unique_ptr<PsfModel> model;
  double fNumber = 0.0;         // the exposure's: with blades, the polygon's equal-area f-number
  std::string stopText;         // "round", "6 blades at 10 deg", "mask heart.png ..."
  std::string summary() const;  // the view's summary, the field and the stop
};

// Validates (UsageError naming the option), loads, stops down, focuses, and
// traces the pupils (InputError naming the lens: an afocal or diverging
// lens, a field beyond the lens's coverage).
LensWave prepareLensWave(const LensViewOptions& view, const LensWaveOptions& wave, Warnings& warnings);
LensWave prepareLensWave(const UserLens& lens, const LensViewOptions& view, const LensWaveOptions& wave,
                         Warnings& warnings);

// "486.1,587.6" -> numbers; `option` names the flag in the UsageError.
std::vector<double> parseNumberList(const std::string& text, const std::string& option);

// The PSF's sampling and figures as JSON: the pupil grid, the FFT size and
// padding, the PSF's sample spacing, the largest OPD step and whether the
// PSF aliases, and per wavelength the RMS and peak-to-valley OPD and Strehl.
nlohmann::json psfSummaryJson(const LensWave& wave, const Psf& psf);
// One line on the sampling, for the command's standard error and plots.
std::string samplingText(const Psf& psf);

}  // namespace lensrt
