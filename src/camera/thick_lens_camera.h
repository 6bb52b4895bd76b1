#pragma once

#include "camera/aperture.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "optics/chromatic.h"
#include "optics/paraxial.h"

namespace lensrt {

// The first-order model of a real lens: focal length, both principal planes,
// both pupils. Positions are lens-space z (mm, +z toward the film, any origin).
struct ThickLensParams {
  double focalLengthMm = 50.0;
  double frontPrincipalZ = 0.0;  // H
  double rearPrincipalZ = 0.0;   // H'; thickness t = H' - H
  double entrancePupilZ = 0.0;   // the camera origin
  double exitPupilZ = 0.0;
  double exitPupilDiameter = 0.0;      // at `fNumber`
  double entrancePupilDiameter = 0.0;  // at `fNumber` (= f / N)
  double fNumber = 2.8;
  double focusMetres = 10.0;  // from the entrance pupil; +infinity allowed
  ApertureShape aperture;
  std::string lensName;
  // Dispersion of the lens: each sample's focal length is focalLengthMm
  // times this ratio at its wavelength, principal planes and pupils kept
  // (axial colour). None: every wavelength alike.
  std::optional<FocalLengthRatio> dispersion;
  // The film's shift and tilt (lens_movements.h), the tilt about the point
  // where the axis meets the film; focusMetres is then where the plane of
  // focus crosses the axis.
  LensMovements movements;
  // --diffraction on: rays bent by the entrance pupil's far field (stop_diffraction.h).
  bool diffraction = false;
};

// Cardinal points and pupils of a lens's paraxial data, at f-number `fNumber`
// (<= 0: the lens's own), focused at `focusMetres`.
ThickLensParams thickLensFromParaxial(const ParaxialData& p, double fNumber, double focusMetres);

// The vertical field of view (radians) of a lens focused at `focusMetres`
// from its entrance pupil (infinity allowed), on a sensor `sensorHeightMm`
// tall: the angle, seen from the entrance pupil, of the in-focus plane's
// region that images onto the sensor. It narrows as the lens focuses closer
// (focus breathing); a pinhole given it shows the in-focus plane as the lens does.
double lensVerticalFov(const ParaxialData& p, double focusMetres, double sensorHeightMm);

// The seed's thick-lens projection: perspective about the front principal
// point, shifted by the thickness t = H'H: an object point at distance z in
// front of H and height x images at z' = f z / (z - f) behind H' (the seed
// writes z < 0 in front: z' = f z / (z + f) + t from H), height
// x' = -(z'/z) x. Rays: film point -> exit pupil sample -> the rear principal
// plane; the object-side ray leaves the front principal plane at the same
// height toward the film point's conjugate.
//
// Radiometry as the thin lens's, with the exit pupil: E/L = A_xp cos^4 / L_xp^2,
// L_xp the film to exit pupil distance, which is pi / (4 N^2) at infinity.
//
// Movements: each film point of a tilted film images its own conjugate
// plane (its distance from H' sets it), so the plane of focus is the
// Scheimpflug plane exactly, its hinge line at f / sin(tilt) from H in the
// plane through H parallel to the film; the weight's cos at the film is
// against the tilted normal (chief ray toward the exit pupil's centre).
class ThickLensCamera final : public Camera {
 public:
  ThickLensCamera(const Transform& worldFromCamera, const FilmGeometry& film, const ThickLensParams& params,
                  const Exposure& exposure = {});

  std::string describe() const override;
  CameraInfo info() const override;
  bool tracesWavelengths() const override { return params_.dispersion.has_value(); }
  const ThickLensParams& params() const { return params_; }
  double filmZ() const { return filmZ_; }
  // Object distance from H and image distance from H' (mm) of the focus plane.
  double objectDistanceFromH() const { return u_; }
  double imageDistance() const { return v_; }
  ProjectedPoint projectCameraPoint(const Vec3d& point, double wavelengthNm) const override;
  ProjectedRay unprojectRaster(const Vec2d& raster, double wavelengthNm) const override;

 protected:
  std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const override;

 private:
  // generateCameraSpaceRay on the tilted film.
  std::optional<CameraRay> tiltedRay(const CameraSample& sample) const;

  ThickLensParams params_;
  Exposure exposure_;
  Aperture exitPupil_;
  // K of the chief ray's image, film = K t (projectCameraPoint), at a wavelength.
  double chiefRayScale(double wavelengthNm) const;
  // How far the chief ray's film point moves per mm along the axis, per unit of t.
  double chiefRaySlope(double wavelengthNm) const;

  double u_ = 0.0, v_ = 0.0, filmZ_ = 0.0;
  double onAxisWeight_ = 0.0;
  // Per camera, not per ray: where along film -> exit pupil the ray crosses
  // H' (a fraction), and the film's distance to the exit pupil.
  double toRearPrincipal_ = 0.0, filmToExitPupil_ = 0.0;
  MovedFilm movedFilm_;
};

}  // namespace lensrt
