// The point spread function (PSF) of a field point, by FFT of its pupil
// function (optics/pupil_function.h), as Zemax's "FFT PSF".
//
// Design notes: docs/design/psf.md.
#pragma once

#include <memory>
#include <vector>

#include "core/vec.h"
#include "optics/distortion.h"
#include "optics/fft.h"
#include "optics/glass.h"
#include "optics/lens_system.h"
#include "optics/pupil_function.h"

namespace lensrt {

struct PsfSettings {
  FieldPoint field;
  double filmDistanceMm = 0.0;  // rear vertex -> film
  // The first is the primary: the reference sphere is centred on its chief
  // ray's image. Weights >= 0, not all 0.
  std::vector<double> wavelengthsNm{kWavelengthDNm, kWavelengthFNm, kWavelengthCNm};
  std::vector<double> weights{1.0, 1.0, 1.0};
  // Grid points across the pupil at the shortest wavelength (odd, >= 9), or
  // 0: automatic (65, doubled until the OPD step is below a quarter wave).
  int pupilSamples = 0;
  int padding = 4;  // FFT size over pupil samples, >= 2
  StopTransmittance stop;
};

struct PsfWavelength {
  double wavelengthNm = 0.0;
  double weight = 0.0;        // normalised: the weights sum to 1
  int pupilSamples = 0;       // grid points across the pupil at this wavelength
  double pupilSpacing = 0.0;  // direction cosines between samples
  double rmsWaves = 0.0, peakToValleyWaves = 0.0, maxStepWaves = 0.0;  // PupilFunction's
  double strehl = 0.0;  // the PSF's peak over the diffraction limit's
  // The pupil's extent, max(L) - min(L) and max(M) - min(M) of the lit
  // samples: the MTF's cutoff along x is extent.x / lambda.
  Vec2d extent;
};

struct Psf {
  int size = 0;  // size x size samples
  double pixelMm = 0.0;
  Vec2d originMm;        // film (x, y) of sample (size/2, size/2)
  int pupilSamples = 0;  // across the pupil at the shortest wavelength
  int padding = 0;
  // Row by row (y): the fraction of the field point's light (at unit total
  // weight) on each sample. They sum to `windowLight`, a little below 1: the
  // rest is what the pupil's sharp edge diffracts beyond the window.
  std::vector<double> intensity;
  double windowLight = 0.0;
  // The same pupils without their OPD: the diffraction limit, to the same scale.
  std::vector<double> limit;
  std::vector<PsfWavelength> wavelengths;
  double strehl = 0.0;        // peak over the limit's peak
  double maxStepWaves = 0.0;  // over the wavelengths
  bool aliased() const { return maxStepWaves >= 0.5; }
  // The highest frequency (cycles/mm) any wavelength passes along x and y.
  Vec2d cutoffPerMm;

  // Sample (i, j)'s position relative to originMm, mm.
  Vec2d offsetMm(int i, int j) const { return {(i - size / 2) * pixelMm, (j - size / 2) * pixelMm}; }
  double at(int i, int j) const { return intensity[std::size_t(j) * std::size_t(size) + std::size_t(i)]; }
  Vec2d centroidMm() const;    // relative to originMm
  double rmsRadiusMm() const;  // about the centroid
};

// A field point's pupils, traced once; its PSF at any film position.
class PsfModel {
 public:
  // Throws InputError(the lens's name) when the field's chief ray does not
  // pass (beyond the lens's coverage) and std::invalid_argument for bad
  // settings (no wavelengths, weights not matching, pupil samples, padding).
  PsfModel(const LensSystem& lens, PsfSettings settings);
  ~PsfModel();
  PsfModel(PsfModel&&) noexcept;

  // `filmShiftMm` moves the film along the axis (+: away from the lens).
  Psf psf(double filmShiftMm = 0.0) const;
  // The primary wavelength's pupil function at that film position.
  PupilFunction pupilFunction(double filmShiftMm = 0.0) const;
  const PsfSettings& settings() const { return settings_; }

 private:
  struct Wavelength;
  LensSystem lens_;  // a copy: the model outlives (or moves away from) its caller's
  PsfSettings settings_;
  PupilBeam primaryBeam_;
  int pupilSamples_ = 0;
  int fftSize_ = 0;
  double pixelMm_ = 0.0;
  std::vector<Wavelength> wavelengths_;
};

// The fraction of the PSF's energy within `radiusMm` of `centreMm` (relative
// to originMm), from its Fourier series: exact for the sampled (band-limited)
// intensity, not a sum of pixels. `limit`: of the diffraction limit.
// The PSF's discrete spectrum (the unnormalised OTF on the FFT grid; `limit`:
// of the diffraction-limited PSF), shared by the MTF and encircled energy.
ComplexGrid psfSpectrum(const Psf& psf, bool limit = false);
double encircledEnergy(const Psf& psf, double radiusMm, Vec2d centreMm = {}, bool limit = false);
// The same at many radii (one transform).
std::vector<double> encircledEnergy(const Psf& psf, const std::vector<double>& radiiMm, Vec2d centreMm = {},
                                    bool limit = false);

}  // namespace lensrt
