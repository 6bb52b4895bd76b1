#pragma once

#include <array>
#include <memory>

#include "camera/aperture.h"
#include "camera/aperture_mask.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "camera/wavelength_lanes.h"
#include "core/warnings.h"
#include "optics/chief_ray.h"
#include "optics/exit_pupil.h"
#include "optics/lens_system.h"

namespace lensrt {

struct LensCameraParams {
  double fNumber = 0.0;            // <= 0: the lens wide open
  double focusMetres = kInfinity;  // from the entrance pupil; +infinity allowed
  ApertureShape aperture;          // blades cut the (round) stop to a polygon of the f-number's area
  // Trace each sample at its own wavelength (dispersion) when the lens has
  // dispersion data (chromatic.h: hasDispersion). Off: every ray at the d
  // line, where the focus is computed. The CLI turns it on by default.
  bool dispersion = false;
  int pupilIntervals = 64;  // exit pupil bounds resolution over the film radius
  // Fresnel losses at every refracting surface (optics/coating.h): each
  // ray's weight times its transmittance. nullopt: lossless glass.
  std::optional<Coating> coatings;
  // A grey-scale mask over the stop (camera/aperture_mask.h): each ray's
  // weight times the mask where it crosses the stop. Null: the open stop.
  std::shared_ptr<const ApertureMask> mask;
  // --diffraction on: rays bent by the entrance pupil's far field, the
  // stop's shape (blades, mask) at the pupil's size (stop_diffraction.h).
  bool diffraction = false;
  // Stray light (lens flare): the most reflections a path takes in the lens
  // (LensSystem::traceFromFilmWithFlare), none: off. Needs coatings set (the
  // reflectance). Blades and a mask shape the stop at every crossing, so
  // the ghosts that pass it take its shape.
  std::optional<int> flareReflections;
  // With flare: the barrel's diffuse reflectance in [0, 1) (LensSystem::FlareOptions).
  double barrelReflectance = 0.0;
  // The film's shift and tilt (lens_movements.h), the tilt about the point
  // where the axis meets the film; focusMetres is then where the plane of
  // focus crosses the axis.
  LensMovements movements;
  // Spectral transport: weigh the secondary wavelengths of each sample
  // (camera/wavelength_lanes.h) so its path carries all four past the lens.
  // Off: the path goes on at the hero alone (for tests that compare both).
  bool carryLanes = true;
};

// The full element stack (Kolb et al. 1995): film point -> a point inside the
// exit pupil bounds on the rear-vertex plane -> exact trace through every
// surface -> the scene. Rays the stop, a rim or total internal reflection
// block return nullopt (vignetting).
//
// Radiometry: E/L = integral over the rear-vertex plane of
// cos(th_film) cos(th_plane) / d^2 dA = dz^2 / d^4 dA, estimated with the
// bounds' pdf; the exposure uses the stopped-down lens's paraxial f-number
// (the requested one with blades).
//
// Movements: the film points move (MovedFilm) and the rest follows: the
// exit pupil bounds reach the largest radius the moved frame does, and a
// tilted film's bounds hold for every depth its points take (each film
// point's passing region depends on its depth too: ExitPupilBounds'
// depth range), so the sampling stays unbiased; the integrand's cos at
// the film is against the tilted normal.
class LensCamera final : public Camera {
 public:
  // Stops the prescription down and focuses it (InputError when it cannot
  // focus that close; a too-wide f-number clamps and warns).
  LensCamera(const Transform& worldFromCamera, const FilmGeometry& film, const LensPrescription& prescription,
             const LensCameraParams& params, const Exposure& exposure, Warnings& warnings);

  std::string describe() const override;
  CameraInfo info() const override;
  // With flare and a single-layer coating the reflectance depends on the
  // wavelength: each sample is traced at its own.
  bool tracesWavelengths() const override {
    return dispersion_ || (params_.flareReflections && params_.coatings == Coating::Single);
  }
  // Not with flare (a ghost's path is its hero's) nor diffraction (a bend
  // drawn at the hero's wavelength).
  bool carriesLanes() const override {
    return dispersion_ && params_.carryLanes && !params_.flareReflections && !params_.diffraction;
  }
  const LensSystem& lens() const { return *lens_; }
  const ExitPupilBounds& bounds() const { return *bounds_; }
  double fNumber() const { return fNumber_; }
  // With flare: how the stray-light traces run (the reflection limit, the
  // barrel, the stop's blades or mask), for the light pass and for tests.
  const LensSystem::FlareOptions& flareOptions() const { return flareOptions_; }
  bool flare() const { return params_.flareReflections.has_value(); }
  // What a pixel records per unit of film irradiance (the exposure scale):
  // a camera ray's weight is this times the irradiance integrand over its pdf.
  double exposureScale() const { return scale_; }
  double filmZ() const { return filmZ_; }
  // Camera space origin (the entrance pupil) in lens space z, mm.
  double entrancePupilZ() const { return entrancePupilZ_; }
  ProjectedPoint projectCameraPoint(const Vec3d& point, double wavelengthNm) const override;
  ProjectedPoint projectCameraPointHinted(const Vec3d& point, double wavelengthNm,
                                          ChiefRayHint* hint) const override;
  ProjectedRay unprojectRaster(const Vec2d& raster, double wavelengthNm) const override;
  // The camera-space ray from a raster position through a point of the
  // rear-vertex plane (lens space x, y in mm), traced at `wavelengthNm`;
  // nullopt when the lens blocks it. The geometry behind generateRay, apart
  // from the sampling, for tests and tools.
  std::optional<Ray> traceThrough(const Vec2f& raster, const Vec2d& pupilPoint,
                                  double wavelengthNm = kWavelengthDNm) const;
  // Where a ray leaving the lens toward the film (lens space) meets the
  // film, as a raster position (possibly outside the image): the flare
  // light pass's deposit.
  Vec2d rasterOfFilmHit(const LensRay& towardFilm) const;
  const LensMovements& movements() const { return params_.movements; }

 protected:
  std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const override;
  void generateCameraSpaceRays(std::span<const CameraSample> samples,
                               std::span<std::optional<CameraRay>> out) const override;

 private:
  // The film point of a sample (lens space) and the ray toward its pupil
  // sample; a zero direction when the film point has no pupil (blocked).
  struct PupilRay {
    LensRay ray;
    double weight = 0.0;  // the irradiance integrand over the pdf, times the exposure scale
  };
  // The same from the film point and its pupil sample (nullopt: none).
  PupilRay pupilRay(const Vec3d& filmPoint, const std::optional<PupilSample>& pupil) const;
  // A raster position's point on the film (lens space, mm): the inverted real image.
  Vec3d filmPointMm(const Vec2f& raster) const;
  // The irradiance integrand for a film point and a pupil-plane point.
  double integrand(const Vec3d& filmPoint, const Vec3d& pupilPoint) const;
  // The exact trace, then the polygonal aperture when blades are set and
  // the mask's transmittance at the stop when there is one.
  std::optional<LensRay> traceLens(const LensRay& in, double wavelengthNm) const;
  std::optional<CameraRay> cameraRay(const std::optional<LensRay>& out, double weight) const;
  // Where a ray leaving the rear toward the film meets it (lens space, mm).
  Vec3d filmHitMm(const LensRay& towardFilm) const;
  // A point on the (moved) film, lens space, as a raster position.
  Vec2d rasterOfFilmPoint(const Vec3d& filmPoint) const;
  // CameraRay::laneWeights for a sample traced at its hero: its film point,
  // pupil sample and the ray that left the lens (camera/wavelength_lanes.h).
  std::array<float, 4> laneWeights(const CameraSample& sample, const Vec3d& filmPoint,
                                   const PupilSample& pupil, const LensRay& out) const;
  // The same outgoing ray traced back from the scene at a secondary wavelength.
  LaneTrace traceLane(const LensRay& fromScene, double wavelengthNm, const Vec2d& pixel) const;
  // --flare on: a pupil-plane point from a mixture of the exit pupil bounds
  // (the image's rays) and the whole rear element (the ghosts' rays, which
  // leave the film outside the bounds), and the stochastic trace.
  std::optional<CameraRay> flareRay(const CameraSample& sample) const;

  LensCameraParams params_;
  Exposure exposure_;
  std::unique_ptr<LensSystem> lens_;
  std::unique_ptr<ExitPupilBounds> bounds_;
  std::unique_ptr<const ChiefRays> chiefRays_;  // the projection's
  std::optional<Aperture> polygon_;             // in the stop plane, when blades are set
  LensSystem::FlareOptions flareOptions_;       // with flare: the limit, the barrel, the stop's shape
  double stopRadius_ = 0.0;                     // of the stopped-down stop (mm): the mask's scale
  double fNumber_ = 0.0;
  double filmZ_ = 0.0;
  double entrancePupilZ_ = 0.0;
  double scale_ = 0.0;  // exposure scale
  bool dispersion_ = false;
  MovedFilm movedFilm_;
};

}  // namespace lensrt
