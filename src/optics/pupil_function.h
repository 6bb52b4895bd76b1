// The pupil function of a field point: the amplitude and the optical path
// difference (OPD) of the wave leaving the lens, from exactly traced rays.
//
// Design notes: docs/design/pupil-function.md.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/vec.h"
#include "optics/distortion.h"
#include "optics/lens_system.h"

namespace lensrt {

// The stop's intensity transmittance at a point (x, y) of its plane (lens
// space, mm), in [0, 1]; empty: the round stop alone. As
// LensSystem::FlareOptions::stop.
using StopTransmittance = std::function<double(double, double)>;

// The passing beam of a field point at one wavelength.
struct PupilBeam {
  double chiefAim = 0.0;  // aim-plane x of the real chief ray (y = 0)
  Vec3d chiefExit;        // the chief ray where it leaves the rear surface
  Vec3d chiefDirection;   // and its unit direction there
  // The largest |L - L0| and |M - M0| of the passing rays, (L0, M0) the chief
  // ray's, plus a margin of a few scan steps.
  double halfWidth = 0.0;
  // d(aim x, aim y) / d(L, M) at the chief ray, row by row.
  double aimPerDirection[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
};

// nullopt when the field's chief ray does not pass (the field is beyond the
// lens's coverage).
std::optional<PupilBeam> pupilBeam(const LensSystem& lens, const FieldPoint& field, double wavelengthNm);

// A square grid of (2 half + 1)^2 exit directions centred on `centre`.
struct PupilGrid {
  Vec2d centre;
  double spacing = 0.0;  // direction cosines between neighbours
  int half = 0;
  int size() const { return 2 * half + 1; }
  Vec2d direction(int i, int j) const {
    return {centre.x + (i - half) * spacing, centre.y + (j - half) * spacing};
  }
};

// Where a reference sphere sits: centred on `centre` (the chief ray's image
// on the film), through the chief ray's crossing of the exit pupil's plane.
struct ReferenceSphere {
  Vec3d centre;
  double radiusMm = 0.0;
};
// The reference sphere of a beam's chief ray for the film plane z = filmZ.
ReferenceSphere referenceSphere(const LensSystem& lens, const PupilBeam& beam, double filmZ);

struct PupilFunction {
  PupilGrid grid;
  double wavelengthNm = 0.0;
  // size() x size(), row j (M) by row, i (L) along a row; amplitude 0 where
  // no light passes (and the OPD there is 0).
  std::vector<double> amplitude;
  std::vector<double> opdWaves;
  ReferenceSphere reference;
  // Over the passing pupil, each sample weighted by its light: the RMS
  // and peak-to-valley of the OPD about its mean (piston removed, tilt kept:
  // a tilt is the image's offset from the reference point).
  double rmsWaves = 0.0;
  double peakToValleyWaves = 0.0;
  // The largest OPD change between neighbouring passing samples. Below half
  // a wave the wave is sampled above its Nyquist rate: every ray lands inside
  // the FFT's window, and the PSF does not wrap around (alias).
  double maxStepWaves = 0.0;
  // The light through the pupil: the sum of the samples' intensities, an
  // edge cell's being the mean of its sub-rays' (not its mean amplitude
  // squared: the difference is the light its sharp edge diffracts far out,
  // beyond the FFT's window).
  double light = 0.0;
};

// The rays of one field point and wavelength over a pupil grid, traced once;
// the pupil function for any film plane (through focus) from them.
class PupilRays {
 public:
  // `beam` from pupilBeam at the same wavelength.
  PupilRays(const LensSystem& lens, const FieldPoint& field, double wavelengthNm, const PupilBeam& beam,
            const PupilGrid& grid, const StopTransmittance& stop = {});

  // The pupil function against `reference` (usually one wavelength's
  // referenceSphere for every wavelength, so their PSFs share an origin).
  PupilFunction at(const ReferenceSphere& reference) const;
  const PupilGrid& grid() const { return grid_; }
  double wavelengthNm() const { return wavelengthNm_; }

 private:
  struct Sample {
    Vec3d exit;                  // leaving the rear surface
    Vec3d direction;             // unit
    double opticalPathMm = 0.0;  // from the object's wavefront to `exit`
    double amplitude = 0.0;
    double light = 0.0;  // amplitude^2, or the mean of an edge cell's sub-rays' intensities
  };
  PupilGrid grid_;
  double wavelengthNm_ = 0.0;
  std::vector<Sample> samples_;
  Sample chief_;
};

}  // namespace lensrt
