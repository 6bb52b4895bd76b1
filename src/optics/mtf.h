// The modulation transfer function (MTF): the modulus of the PSF's Fourier
// transform (optics/psf.h), normalised to 1 at zero frequency.
//
// Tangential: frequencies along the field's meridional direction (film x,
// lines parallel to y); sagittal: along y. Frequencies are cycles/mm on the
// film. The FFT gives the MTF at multiples of 1 / (the PSF's window); between
// them it is interpolated linearly (the window is padding x the pupil, so a
// step is at most a 1/(pupil samples) of the cutoff).
#pragma once

#include <vector>

#include "optics/psf.h"

namespace lensrt {

struct MtfCurves {
  std::vector<double> frequencyPerMm;
  std::vector<double> tangential, sagittal;
  // The diffraction limit of the same pupils (no OPD).
  std::vector<double> limitTangential, limitSagittal;
};

// `points` frequencies evenly from 0 to maxFrequencyPerMm (> 0).
MtfCurves mtfCurves(const Psf& psf, double maxFrequencyPerMm, int points);

// The MTF at the FFT's own frequencies along x (tangential) and y
// (sagittal): index k is k / (size x pixelMm) cycles/mm, k = 0..size/2.
struct MtfSamples {
  double stepPerMm = 0.0;
  std::vector<double> tangential, sagittal;
};
MtfSamples mtfSamples(const Psf& psf, bool limit = false);

struct ThroughFocusMtf {
  double frequencyPerMm = 0.0;
  std::vector<double> filmShiftMm;                  // + away from the lens
  std::vector<double> tangential, sagittal, limit;  // limit: the larger of the two directions' limits
};
// The MTF at one frequency as the film moves through `shifts`.
ThroughFocusMtf throughFocusMtf(const PsfModel& model, double frequencyPerMm,
                                const std::vector<double>& shifts);

// The diffraction-limited MTF of a round, uniformly lit pupil:
// (2/pi)(phi - cos phi sin phi), phi = arccos(nu / cutoff); 0 beyond it.
double diffractionLimitedMtf(double frequency, double cutoff);

}  // namespace lensrt
