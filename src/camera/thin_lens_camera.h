#pragma once

#include <optional>

#include "camera/aperture.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "optics/chromatic.h"

namespace lensrt {

struct ThinLensParams {
  double focalLengthMm = 50.0;
  double fNumber = 2.8;
  double focusMetres = 10.0;  // from the lens (= entrance pupil); +infinity allowed
  ApertureShape aperture;
  std::string lensName;  // the lens it stands for, if any (metadata only)
  // Dispersion of the lens it stands for: each sample's focal length is
  // focalLengthMm times this ratio at its wavelength (axial colour only: a
  // thin lens has no lateral colour). None: every wavelength alike.
  std::optional<FocalLengthRatio> dispersion;
  // The film's shift and tilt (lens_movements.h); focusMetres is then where
  // the plane of focus crosses the optical axis.
  LensMovements movements;
  // --diffraction on: rays bent by the aperture's far field (stop_diffraction.h).
  bool diffraction = false;
};

// An ideal thin lens at the camera origin: every point of the focus plane
// images to one film point, the film sits at the image distance
// v = f s / (s - f), and the aperture (entrance = exit pupil) has diameter f/N.
//
// Radiometry: the lens obeys the sine condition, as a corrected real lens
// does, so E/L = A cos^4(theta) / v^2 with theta the chief ray's angle at the
// film: pi cos^4(theta) / (4 N^2) focused at infinity (the seed's formula,
// exactly). Each sample carries that value (uniform aperture sampling).
//
// Movements: a film point off the unmoved film's plane (tilt) images its
// own conjugate plane, 1/s = 1/f - 1/z at its distance z behind the lens,
// so the conjugates of the tilted film form the Scheimpflug plane exactly;
// the weight's cos at the film is then against the tilted normal:
// E/L = A cos(th_film) cos(th_lens) / d^2 along the chief ray.
class ThinLensCamera final : public Camera {
 public:
  // Throws std::invalid_argument for f <= 0, N <= 0 or a focus at or inside f.
  ThinLensCamera(const Transform& worldFromCamera, const FilmGeometry& film, const ThinLensParams& params,
                 const Exposure& exposure = {});

  std::string describe() const override;
  CameraInfo info() const override;
  bool tracesWavelengths() const override { return params_.dispersion.has_value(); }
  const ThinLensParams& params() const { return params_; }
  double imageDistanceMm() const { return v_; }
  const Aperture& aperture() const { return aperture_; }
  ProjectedPoint projectCameraPoint(const Vec3d& point, double wavelengthNm) const override;
  ProjectedRay unprojectRaster(const Vec2d& raster, double wavelengthNm) const override;

 protected:
  std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const override;

 private:
  // generateCameraSpaceRay on the tilted film.
  std::optional<CameraRay> tiltedRay(const CameraSample& sample) const;

  ThinLensParams params_;
  Exposure exposure_;
  Aperture aperture_;
  double v_ = 0.0;             // image distance, mm
  double focusMm_ = 0.0;       // infinity allowed
  double onAxisWeight_ = 0.0;  // exposure scale * A / v^2
  MovedFilm movedFilm_;
};

// Image distance (mm) of an ideal lens of focal length f focused at s (mm, infinity allowed).
double thinLensImageDistance(double focalLengthMm, double focusMm);

}  // namespace lensrt
