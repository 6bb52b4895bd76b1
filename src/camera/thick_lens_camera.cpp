#include "camera/thick_lens_camera.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "camera/film_mapping.h"
#include "camera/thin_lens_camera.h"

namespace lensrt {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

ThickLensParams thickLensFromParaxial(const ParaxialData& p, double fNumber, double focusMetres) {
  ThickLensParams t;
  t.focalLengthMm = p.efl;
  t.frontPrincipalZ = p.frontPrincipalZ;
  t.rearPrincipalZ = p.rearPrincipalZ;
  t.entrancePupilZ = p.entrancePupilZ;
  t.exitPupilZ = p.exitPupilZ;
  t.fNumber = fNumber > 0.0 ? fNumber : p.fNumber;
  // Both pupils are images of the stop: they scale together when it closes.
  const double scale = p.fNumber / t.fNumber;
  t.entrancePupilDiameter = p.entrancePupilDiameter * scale;
  t.exitPupilDiameter = p.exitPupilDiameter * scale;
  t.focusMetres = focusMetres;
  return t;
}

double lensVerticalFov(const ParaxialData& p, double focusMetres, double sensorHeightMm) {
  const double half = sensorHeightMm / 2.0;
  if (std::isinf(focusMetres)) return 2.0 * std::atan(half / p.efl);
  const double s = focusMetres * 1000.0;
  const double u = s + (p.frontPrincipalZ - p.entrancePupilZ);  // object distance from H
  const double v = thinLensImageDistance(p.efl, u);
  return 2.0 * std::atan(half * (u / v) / s);
}

ThickLensCamera::ThickLensCamera(const Transform& worldFromCamera, const FilmGeometry& film,
                                 const ThickLensParams& params, const Exposure& exposure)
    : Camera(worldFromCamera, film),
      params_(params),
      exposure_(exposure),
      exitPupil_(params.exitPupilDiameter / 2.0, params.aperture),
      movedFilm_(params.movements) {
  const double f = params.focalLengthMm;
  if (!(f > 0.0)) throw std::invalid_argument("thick lens: focal length must be positive");
  const double s = params.focusMetres * 1000.0;
  if (std::isinf(s)) {
    u_ = s;
  } else {
    u_ = s + (params.frontPrincipalZ - params.entrancePupilZ);
    if (!(u_ > f)) throw std::invalid_argument("thick lens: cannot focus inside the front focal point");
  }
  v_ = thinLensImageDistance(f, u_);
  filmZ_ = params.rearPrincipalZ + v_;
  const double lxp = filmZ_ - params.exitPupilZ;
  if (!(lxp > 0.0)) throw std::invalid_argument("thick lens: the exit pupil lies behind the film");
  onAxisWeight_ = exposureScale(exposure, params.fNumber) * exitPupil_.area() / (lxp * lxp);
  toRearPrincipal_ = (params.rearPrincipalZ - filmZ_) / (params.exitPupilZ - filmZ_);
  filmToExitPupil_ = lxp;
  // The entrance pupil: the exit pupil's shape at the entrance pupil's size.
  if (params.diffraction)
    setDiffraction(std::make_shared<const StopDiffraction>(
        StopDiffraction::apertureStop(exitPupil_),
        exitPupil_.circumradius() * params.entrancePupilDiameter / params.exitPupilDiameter));
  checkLensMovements(params.movements, film, "thick lens");
  if (params.movements.tilted()) {
    const double nearest = filmZ_ + movedFilm_.depthRange(film).min;
    if (!(nearest > params.exitPupilZ && nearest > params.rearPrincipalZ))
      throw std::invalid_argument(
          "thick lens: the tilted film reaches the exit pupil or the rear principal plane");
  }
}

std::string ThickLensCamera::describe() const {
  char buf[240];
  std::snprintf(buf, sizeof buf, "thick lens f=%gmm t=%gmm f/%g focus=%s aperture=%s", params_.focalLengthMm,
                params_.rearPrincipalZ - params_.frontPrincipalZ, params_.fNumber,
                focusText(params_.focusMetres).c_str(), lensrt::describe(params_.aperture).c_str());
  return std::string(buf) + (params_.dispersion ? " dispersion=on" : "") +
         (params_.diffraction ? " diffraction=on" : "") + params_.movements.describe();
}

CameraInfo ThickLensCamera::info() const {
  CameraInfo i{"thick",
               params_.lensName,
               params_.fNumber,
               params_.focusMetres,
               params_.focalLengthMm,
               lensrt::describe(exposure_),
               params_.dispersion.has_value()};
  i.movements = params_.movements;
  i.entrancePupilOffsetMm = filmZ_ - params_.entrancePupilZ;  // lens space: +z toward the film
  return i;
}

std::optional<CameraRay> ThickLensCamera::generateCameraSpaceRay(const CameraSample& s) const {
  if (params_.movements.tilted()) return tiltedRay(s);
  const ThickLensParams& P = params_;
  Vec2d up = uprightSensorPointMm(film(), s.film);
  if (P.movements.shifted()) up = up + P.movements.shiftMm;
  const Vec3d p{-up.x, -up.y, filmZ_};  // the inverted real image
  const Vec2d e = exitPupil_.sample({s.lens.x, s.lens.y});
  const Vec3d q{e.x, e.y, P.exitPupilZ};
  // Where the image-side ray crosses H'; it leaves H at the same height.
  const Vec3d a = p + (q - p) * toRearPrincipal_;
  const Vec3d origin{a.x, a.y, P.frontPrincipalZ};
  Vec3d dir;
  if (P.dispersion) {
    // The film (at v for the d line) is conjugate at this wavelength to the
    // plane 1/u = 1/f(l) - 1/v in front of H (beyond infinity when negative).
    const double invU = 1.0 / (P.focalLengthMm * P.dispersion->at(s.wavelengthNm)) - 1.0 / v_;
    dir = {up.x / v_ - a.x * invU, up.y / v_ - a.y * invU, -1.0};
  } else if (std::isinf(u_)) {
    dir = {up.x, up.y, -v_};  // parallel to the chief ray through the nodal points
  } else {
    const double k = u_ / v_;
    dir = Vec3d{up.x * k, up.y * k, P.frontPrincipalZ - u_} - origin;
  }
  const float weight = float(onAxisWeight_ * cos4ToAxis(up.x, up.y, filmToExitPupil_));
  const Vec3d o = Vec3d{origin.x, origin.y, origin.z - P.entrancePupilZ} * 1e-3;
  return CameraRay{Ray{Vec3f(o), Vec3f(normalize(dir))}, weight};
}

std::optional<CameraRay> ThickLensCamera::tiltedRay(const CameraSample& s) const {
  const ThickLensParams& P = params_;
  const Vec3d p = Vec3d{0.0, 0.0, filmZ_} + movedFilm_.offset(uprightSensorPointMm(film(), s.film));
  const Vec2d e = exitPupil_.sample({s.lens.x, s.lens.y});
  const Vec3d q{e.x, e.y, P.exitPupilZ};
  // Where the image-side ray crosses H' (this film point's own fraction);
  // it leaves H at the same height toward p's conjugate, at
  // 1/u = 1/f - 1/v in front of H for p's distance v behind H' (beyond
  // infinity when negative): per unit of depth -p/v through the nodal
  // points and -a/u from the height a.
  const Vec3d a = p + (q - p) * ((P.rearPrincipalZ - p.z) / (q.z - p.z));
  const double v = p.z - P.rearPrincipalZ;
  const double f = P.dispersion ? P.focalLengthMm * P.dispersion->at(s.wavelengthNm) : P.focalLengthMm;
  const double invU = 1.0 / f - 1.0 / v;
  const Vec3d dir{-p.x / v - a.x * invU, -p.y / v - a.y * invU, -1.0};
  // The chief ray toward the exit pupil's centre: cos against the film's
  // normal and the axis over the distance squared, relative to the untilted
  // centre's L_xp^2 / L_xp^4 that onAxisWeight_ holds.
  const Vec3d toPupil = Vec3d{0.0, 0.0, P.exitPupilZ} - p;
  const double d2 = lengthSquared(toPupil);
  const double cosFilmCosPupil = dot(movedFilm_.normal(), toPupil) * -toPupil.z / (d2 * d2);
  const float weight = float(onAxisWeight_ * filmToExitPupil_ * filmToExitPupil_ * cosFilmCosPupil);
  const Vec3d o = Vec3d{a.x, a.y, P.frontPrincipalZ - P.entrancePupilZ} * 1e-3;
  return CameraRay{Ray{Vec3f(o), Vec3f(normalize(dir))}, weight};
}

// The chief ray enters toward the entrance pupil's centre E (the camera
// origin) with slope t = dx/dz, crosses H at height a = t (z_H - z_E),
// leaves H' at that height with slope t - a / f (the paraxial refraction)
// and meets the film D = z_film - z_H' behind: at K t, where
// K = (z_H - z_E) + D (1 - (z_H - z_E) / f). Every point of the line
// through E images there; the thin lens is the case z_H = z_H' = z_E, K = v.
double ThickLensCamera::chiefRayScale(double wavelengthNm) const {
  const ThickLensParams& P = params_;
  return (P.frontPrincipalZ - P.entrancePupilZ) + (filmZ_ - P.rearPrincipalZ) * chiefRaySlope(wavelengthNm);
}

// Behind H' the chief ray moves by t (1 - (z_H - z_E) / f) per mm: with
// chiefRayScale's K t at the film's plane, the line a moved film meets.
double ThickLensCamera::chiefRaySlope(double wavelengthNm) const {
  const ThickLensParams& P = params_;
  const double f = P.focalLengthMm * (P.dispersion ? P.dispersion->at(wavelengthNm) : 1.0);
  return 1.0 - (P.frontPrincipalZ - P.entrancePupilZ) / f;
}

ProjectedPoint ThickLensCamera::projectCameraPoint(const Vec3d& p, double wavelengthNm) const {
  if (!(p.z < 0.0) || !isFinite(p)) return {{kNaN, kNaN}, Visibility::Behind};
  if (params_.movements.any()) {
    const Vec2d t{p.x / p.z, p.y / p.z};
    const std::optional<Vec2d> up =
        movedFilm_.uprightOfLine(t * chiefRayScale(wavelengthNm), t * chiefRaySlope(wavelengthNm));
    if (!up) return {{kNaN, kNaN}, Visibility::Behind};
    const Vec2d raster = rasterOfUprightSensorPointMm(film(), *up);
    return {raster, frameVisibility(film(), raster)};
  }
  // t = p.xy / p.z; the upright image is the film point's negative.
  const Vec2d raster =
      rasterOfUprightSensorPointMm(film(), Vec2d{p.x, p.y} * (chiefRayScale(wavelengthNm) / -p.z));
  return {raster, frameVisibility(film(), raster)};
}

ProjectedRay ThickLensCamera::unprojectRaster(const Vec2d& raster, double wavelengthNm) const {
  const Vec2d up = uprightSensorPointOfRaster(film(), raster);
  const double k = chiefRayScale(wavelengthNm);
  if (params_.movements.any()) {
    // The film point (relative to the pivot) on the chief ray's line: K t + c t z.
    const Vec3d q = movedFilm_.offset(up);
    const Vec2d t = Vec2d{q.x, q.y} * (1.0 / (k + chiefRaySlope(wavelengthNm) * q.z));
    return {{0.0, 0.0, 0.0}, normalize(Vec3d{-t.x, -t.y, -1.0}), frameVisibility(film(), raster)};
  }
  return {{0.0, 0.0, 0.0}, normalize(Vec3d{up.x / k, up.y / k, -1.0}), frameVisibility(film(), raster)};
}

}  // namespace lensrt
