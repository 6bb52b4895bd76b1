// SVG plots and tables of a lens's wave optics (api/lens_wave.h): the PSF
// (`lens psf`) and the MTF (`lens mtf`).
#pragma once

#include "api/lens_wave.h"
#include "optics/mtf.h"
#include "report/lens_plot.h"

namespace lensrt {

// Profiles through the PSF's centre along film x and y, relative to the
// diffraction limit's peak (so the peak is the Strehl ratio), and the
// encircled energy about the image point, each with the diffraction limit.
// Columns: offset_um, psf_x, psf_y, limit_x, limit_y, encircled_energy,
// limit_encircled_energy (the energies at radius |offset|, for offset >= 0;
// nan before).
LensPlot plotPsf(const LensWave& wave, const Psf& psf);

// The MTF against frequency (tangential, sagittal, the diffraction limit),
// and through focus at one frequency. Columns: frequency_per_mm, tangential,
// sagittal, limit_tangential, limit_sagittal, film_shift_um,
// through_focus_tangential, through_focus_sagittal, through_focus_limit (the
// two curves side by side, nan where one is shorter).
LensPlot plotMtf(const LensWave& wave, const Psf& psf, const MtfCurves& mtf, const ThroughFocusMtf& focus);

}  // namespace lensrt
