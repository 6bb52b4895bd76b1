// What the colours of one camera sample are carried as: RGB, or (spectral
// transport) the radiance at four wavelengths, a hero wavelength and three
// copies rotated by a quarter of the range (pbrt-v4's SampledWavelengths).
// The scene's colours are linear Rec. 709 RGB (glTF); each is turned into the
// sample's Spectrum where it enters a path, and the path's radiance back into
// the film's RGB at the end:
// - reflectances (base, sheen, attenuation colour) are upsampled to smooth
//   spectra (Jakob and Hanika 2019, color/rgb_to_spectrum.h);
//
// Design notes: docs/design/wavelengths.md.
#pragma once

#include <array>
#include <memory>

#include "core/vec.h"
#include "render/spectrum.h"

namespace lensrt {

class FilmResponse;

class SampledWavelengths {
 public:
  // RGB transport: every conversion keeps the RGB value (spectrum.h).
  static SampledWavelengths rgb() { return SampledWavelengths(); }
  // Spectral transport: four wavelengths from u in [0, 1), drawn from the
  // response's sampling density.
  static SampledWavelengths sample(float u, const FilmResponse& response);

  bool spectral() const { return spectral_; }
  // The wavelength a dispersive event follows (nm).
  float hero() const { return nm_[0]; }
  float nm(std::size_t lane) const { return nm_[lane]; }

  // A reflectance in [0, 1] (values outside are clamped).
  Spectrum reflectance(const Rgb& c) const { return spectral_ ? upsampleReflectance(c) : Spectrum(c); }
  // A non-negative factor that may exceed 1 (KHR_materials_specular's tint).
  Spectrum unbounded(const Rgb& c) const { return spectral_ ? upsampleUnbounded(c) : Spectrum(c); }
  // Emitted radiance (emission, lights, the environment).
  Spectrum illuminant(const Rgb& c) const { return spectral_ ? upsampleIlluminant(c) : Spectrum(c); }

  // The secondary wavelengths stop here: their film weights drop to 0 and the
  // hero's is multiplied by 4 (RGB transport has none to drop).
  void terminateSecondary();
  bool secondaryTerminated() const { return terminated_; }
  // Each lane's film weight times its factor (a camera's
  // CameraRay::laneWeights: the path carries all four past a dispersive
  // lens); a lane with factor 0 stops. A later terminateSecondary() starts
  // from the plain weights again: past a dispersive event only the hero's
  // own trace makes the path.
  void weightLanes(const std::array<float, Spectrum::kLanes>& factors);
  // 1 in the lanes that still reach the film, 0 in the others: a path's
  // throughput is masked with it so that roulette sees the live lanes only.
  Spectrum liveLanes() const { return terminated_ ? Spectrum(1, 0, 0, 0) : live_; }

  // A path's radiance in the film's RGB.
  Rgb toFilm(const Spectrum& radiance) const;

 private:
  SampledWavelengths() = default;
  Spectrum upsampleReflectance(const Rgb& c) const;
  Spectrum upsampleUnbounded(const Rgb& c) const;
  Spectrum upsampleIlluminant(const Rgb& c) const;

  bool spectral_ = false;
  bool terminated_ = false;
  std::array<float, Spectrum::kLanes> nm_{550, 550, 550, 550};
  Spectrum illuminant_{1.0f};                        // the output white's illuminant at nm_
  std::array<Rgb, Spectrum::kLanes> filmWeight_{};   // c(l) / (4 pdf(l)), times the lane's factor
  std::array<Rgb, Spectrum::kLanes> plainWeight_{};  // c(l) / (4 pdf(l))
  Spectrum live_{1.0f};
};

}  // namespace lensrt
