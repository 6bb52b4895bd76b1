#include "camera/lens_camera.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "camera/film_mapping.h"
#include "optics/focus.h"

namespace lensrt {

LensCamera::LensCamera(const Transform& worldFromCamera, const FilmGeometry& film,
                       const LensPrescription& prescription, const LensCameraParams& params,
                       const Exposure& exposure, Warnings& warnings)
    : Camera(worldFromCamera, film), params_(params), exposure_(exposure) {
  const ParaxialData open = computeParaxial(prescription);
  double n = params.fNumber > 0.0 ? params.fNumber : open.fNumber;
  // A polygon of the f-number's area needs a round stop as wide as its corners.
  const double widen = polygonCircumradiusFactor(params.aperture.blades);
  LensPrescription stopped = stopDown(prescription, n / widen, warnings);
  lens_ = std::make_unique<LensSystem>(std::move(stopped));
  const ParaxialData& p = lens_->paraxial();
  fNumber_ = p.fNumber * widen;
  entrancePupilZ_ = p.entrancePupilZ;
  if (params.aperture.blades) {
    const double stopRadius = lens_->prescription().surfaces[p.stopIndex].apertureDiameter / 2.0;
    polygon_.emplace(stopRadius / widen, params.aperture);
  }
  filmZ_ = lens_->rearZ() + focusFilmDistance(*lens_, params.focusMetres * 1000.0);
  bounds_ = std::make_unique<ExitPupilBounds>(*lens_, filmZ_, sensorHalfDiagonalMm(film) * (1.0 + 1e-6),
                                              params.pupilIntervals);
  scale_ = exposureScale(exposure, fNumber_);
}

std::string LensCamera::describe() const {
  char buf[240];
  std::snprintf(buf, sizeof buf, "lens %s f=%.4gmm f/%.3g focus=%gm aperture=%s",
                lens_->prescription().name.c_str(), lens_->paraxial().efl, fNumber_, params_.focusMetres,
                lensrt::describe(params_.aperture).c_str());
  return buf;
}

CameraInfo LensCamera::info() const {
  return {"lens",
          lens_->prescription().name,
          fNumber_,
          params_.focusMetres,
          lens_->paraxial().efl,
          lensrt::describe(exposure_)};
}

namespace {

// E/L integrand over the rear-vertex plane, parallel to the film:
// cos(th_film) cos(th_plane) / d^2 = dz^2 / d^4.
double irradianceIntegrand(const Vec3d& filmPoint, const Vec3d& pupilPoint) {
  const double dz = filmPoint.z - pupilPoint.z;
  const double d2 = lengthSquared(pupilPoint - filmPoint);
  return dz * dz / (d2 * d2);
}

}  // namespace

std::optional<Ray> LensCamera::traceThrough(const Vec2f& raster, const Vec2d& pupilPoint,
                                            double wavelengthNm) const {
  const Vec2d up = uprightSensorPointMm(film(), raster);
  const Vec3d p{-up.x, -up.y, filmZ_};  // the inverted real image
  const LensRay in{p, Vec3d{pupilPoint.x, pupilPoint.y, bounds_->planeZ()} - p};
  std::optional<LensRay> out;
  if (polygon_) {
    std::vector<Vec3d> path;
    path.reserve(lens_->surfaceCount());
    out = lens_->traceFromFilm(in, wavelengthNm, &path);
    // The path runs from the rear surface to the front one.
    if (out) {
      const Vec3d& hit = path.at(lens_->surfaceCount() - 1 - lens_->paraxial().stopIndex);
      if (!polygon_->contains({hit.x, hit.y})) out.reset();
    }
  } else {
    out = lens_->traceFromFilm(in, wavelengthNm);
  }
  if (!out) return std::nullopt;
  const Vec3d o = Vec3d{out->origin.x, out->origin.y, out->origin.z - entrancePupilZ_} * 1e-3;
  return Ray{Vec3f(o), Vec3f(out->direction)};
}

std::optional<CameraRay> LensCamera::generateCameraSpaceRay(const CameraSample& s) const {
  const Vec2d up = uprightSensorPointMm(film(), s.film);
  const Vec3d p{-up.x, -up.y, filmZ_};
  const std::optional<PupilSample> ps = bounds_->sample({p.x, p.y}, {s.lens.x, s.lens.y});
  if (!ps) return std::nullopt;
  const double wavelength = params_.dispersion ? double(s.wavelengthNm) : kWavelengthDNm;
  const std::optional<Ray> ray = traceThrough(s.film, {ps->point.x, ps->point.y}, wavelength);
  if (!ray) return std::nullopt;
  return CameraRay{*ray, float(scale_ * irradianceIntegrand(p, ps->point) / ps->pdf)};
}

}  // namespace lensrt
