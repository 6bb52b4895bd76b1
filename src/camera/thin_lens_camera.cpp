#include "camera/thin_lens_camera.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "camera/film_mapping.h"

namespace lensrt {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

double thinLensImageDistance(double f, double s) {
  if (std::isinf(s)) return f;
  return f * s / (s - f);
}

ThinLensCamera::ThinLensCamera(const Transform& worldFromCamera, const FilmGeometry& film,
                               const ThinLensParams& params, const Exposure& exposure)
    : Camera(worldFromCamera, film),
      params_(params),
      exposure_(exposure),
      aperture_(params.focalLengthMm / (2.0 * params.fNumber), params.aperture),
      movedFilm_(params.movements) {
  if (!(params.focalLengthMm > 0.0)) throw std::invalid_argument("thin lens: focal length must be positive");
  focusMm_ = params.focusMetres * 1000.0;
  if (!(focusMm_ > params.focalLengthMm))
    throw std::invalid_argument("thin lens: cannot focus closer than the focal length");
  v_ = thinLensImageDistance(params.focalLengthMm, focusMm_);
  checkLensMovements(params.movements, film, "thin lens");
  if (params.movements.tilted() && !(v_ + movedFilm_.depthRange(film).min > 0.0))
    throw std::invalid_argument("thin lens: the tilted film reaches the lens");
  onAxisWeight_ = exposureScale(exposure, params.fNumber) * aperture_.area() / (v_ * v_);
  // The lens is its own entrance pupil.
  if (params.diffraction)
    setDiffraction(std::make_shared<const StopDiffraction>(StopDiffraction::apertureStop(aperture_),
                                                           aperture_.circumradius()));
}

std::string ThinLensCamera::describe() const {
  char buf[200];
  std::snprintf(buf, sizeof buf, "thin lens f=%gmm f/%g focus=%s aperture=%s", params_.focalLengthMm,
                params_.fNumber, focusText(params_.focusMetres).c_str(),
                lensrt::describe(params_.aperture).c_str());
  return std::string(buf) + (params_.dispersion ? " dispersion=on" : "") +
         (params_.diffraction ? " diffraction=on" : "") + params_.movements.describe();
}

CameraInfo ThinLensCamera::info() const {
  CameraInfo i{"thin",
               params_.lensName,
               params_.fNumber,
               params_.focusMetres,
               params_.focalLengthMm,
               lensrt::describe(exposure_),
               params_.dispersion.has_value()};
  i.movements = params_.movements;
  i.entrancePupilOffsetMm = v_;  // the pupil is the lens
  return i;
}

std::optional<CameraRay> ThinLensCamera::generateCameraSpaceRay(const CameraSample& s) const {
  if (params_.movements.tilted()) return tiltedRay(s);
  Vec2d up = uprightSensorPointMm(film(), s.film);
  if (params_.movements.shifted()) up = up + params_.movements.shiftMm;
  // The chief ray through the lens centre leaves along (x, y, -v) (upright
  // sensor coordinates: the physical film point is (-x, -y, +v)).
  const Vec2d q = aperture_.sample({s.lens.x, s.lens.y});
  Vec3d dir;
  if (params_.dispersion) {
    // The film (at v for the d line) is conjugate at this wavelength to the
    // plane 1/s = 1/f(l) - 1/v, which may lie beyond infinity (1/s < 0); the
    // undeviated ray through the centre fixes the direction toward it.
    const double invS = 1.0 / (params_.focalLengthMm * params_.dispersion->at(s.wavelengthNm)) - 1.0 / v_;
    dir = {up.x / v_ - q.x * invS, up.y / v_ - q.y * invS, -1.0};
  } else if (std::isinf(focusMm_)) {
    dir = {up.x, up.y, -v_};
  } else {
    const double k = focusMm_ / v_;  // to the focus plane Z = -s
    dir = Vec3d{up.x * k - q.x, up.y * k - q.y, -focusMm_};
  }
  const float weight = float(onAxisWeight_ * cos4ToAxis(up.x, up.y, v_));
  return CameraRay{Ray{{float(q.x * 1e-3), float(q.y * 1e-3), 0.0f}, Vec3f(normalize(dir))}, weight};
}

std::optional<CameraRay> ThinLensCamera::tiltedRay(const CameraSample& s) const {
  // The physical film point (mm, +z behind the lens).
  const Vec3d p = Vec3d{0.0, 0.0, v_} + movedFilm_.offset(uprightSensorPointMm(film(), s.film));
  const Vec2d q = aperture_.sample({s.lens.x, s.lens.y});
  // Toward p's conjugate, at 1/s = 1/f - 1/z in front (beyond infinity when
  // negative): through the centre undeviated, so per unit of depth the ray
  // moves by -p/z and by -q/s from where it left the lens.
  const double f = params_.dispersion ? params_.focalLengthMm * params_.dispersion->at(s.wavelengthNm)
                                      : params_.focalLengthMm;
  const double invS = 1.0 / f - 1.0 / p.z;
  const Vec3d dir{-p.x / p.z - q.x * invS, -p.y / p.z - q.y * invS, -1.0};
  // The chief ray from p to the lens centre: cos against the film's normal
  // and the lens's axis, over the distance squared, relative to the
  // untilted centre's v^2 / v^4 that onAxisWeight_ holds.
  const double d2 = lengthSquared(p);
  const double cosFilmCosLens = dot(movedFilm_.normal(), -p) * p.z / (d2 * d2);
  const float weight = float(onAxisWeight_ * v_ * v_ * cosFilmCosLens);
  return CameraRay{Ray{{float(q.x * 1e-3), float(q.y * 1e-3), 0.0f}, Vec3f(normalize(dir))}, weight};
}

// The chief ray passes the lens's centre undeviated, at every wavelength
// (the thin lens has no lateral colour), to the film at v.
// The chief ray passes the lens centre undeviated: behind it the line z t,
// t = p.xy / p.z, which meets the film's plane at v t (the inverted image)
// and a moved film where MovedFilm finds it.
ProjectedPoint ThinLensCamera::projectCameraPoint(const Vec3d& p, double) const {
  if (!(p.z < 0.0) || !isFinite(p)) return {{kNaN, kNaN}, Visibility::Behind};
  if (params_.movements.any()) {
    const Vec2d t{p.x / p.z, p.y / p.z};
    const std::optional<Vec2d> up = movedFilm_.uprightOfLine(t * v_, t);
    if (!up) return {{kNaN, kNaN}, Visibility::Behind};
    const Vec2d raster = rasterOfUprightSensorPointMm(film(), *up);
    return {raster, frameVisibility(film(), raster)};
  }
  const Vec2d raster = rasterOfUprightSensorPointMm(film(), Vec2d{p.x, p.y} * (v_ / -p.z));
  return {raster, frameVisibility(film(), raster)};
}

ProjectedRay ThinLensCamera::unprojectRaster(const Vec2d& raster, double) const {
  const Vec2d up = uprightSensorPointOfRaster(film(), raster);
  if (params_.movements.any()) {
    // The film point (relative to the pivot at v) on the line z t.
    const Vec3d q = movedFilm_.offset(up);
    const Vec2d t = Vec2d{q.x, q.y} * (1.0 / (v_ + q.z));
    return {{0.0, 0.0, 0.0}, normalize(Vec3d{-t.x, -t.y, -1.0}), frameVisibility(film(), raster)};
  }
  return {{0.0, 0.0, 0.0}, normalize(Vec3d{up.x, up.y, -v_}), frameVisibility(film(), raster)};
}

}  // namespace lensrt
