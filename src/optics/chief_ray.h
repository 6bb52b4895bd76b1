// The real chief ray of a point: the ray from it through the centre of the
// aperture stop, traced exactly. Where it meets the film is the point's
// image position (the projection a vision pipeline models: the centre of
// the point's blur spot as the stop closes, whatever the focus).
//
// Design notes: docs/design/chief-ray.md.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/vec.h"
#include "optics/chief_ray_hint.h"
#include "optics/glass.h"
#include "optics/lens_system.h"

namespace lensrt {

enum class ChiefRayStatus : std::uint8_t {
  Passes,   // the chief ray passes every surface of the lens
  Blocked,  // a rim, or the lack of any ray through the stop's centre, stops it
  Behind,   // the point is not in front of the lens's front surface
};

// Where a point's chief ray meets the film plane (lens space x, y, mm). With
// Blocked the position is that of the chief ray in the lens with its rims
// opened when one exists, else NaN.
struct ChiefRayImage {
  ChiefRayStatus status = ChiefRayStatus::Blocked;
  Vec2d film;
  // The image-side ray's unit direction (toward the film): where it meets a
  // film off the plane (a shifted or tilted one).
  Vec3d direction{};
};

// The chief ray of a film point, leaving the lens's front surface toward the
// scene (direction.z < 0, unit). Blocked: as above.
struct ChiefRayToScene {
  ChiefRayStatus status = ChiefRayStatus::Blocked;
  LensRay ray;
};

class ChiefRays {
 public:
  // The chief rays of `lens` onto the film plane z = filmZ (copies the lens).
  ChiefRays(const LensSystem& lens, double filmZ);

  // An object point (lens space, mm) in front of the lens.
  ChiefRayImage ofPoint(const Vec3d& point, double wavelengthNm = kWavelengthDNm) const;
  // The same, started from `hint` when it is valid; `hint` then holds this
  // solve's (unchanged when there was none).
  ChiefRayImage ofPoint(const Vec3d& point, double wavelengthNm, ChiefRayHint* hint) const;
  // A point at infinity whose light travels along `direction` (z > 0).
  ChiefRayImage ofDirection(const Vec3d& direction, double wavelengthNm = kWavelengthDNm) const;
  // A film point (x, y on the film plane): the chief ray that lands there.
  ChiefRayToScene ofFilmPoint(const Vec2d& film, double wavelengthNm = kWavelengthDNm) const;
  // The same from a film point off that plane (a tilted film), lens space.
  ChiefRayToScene ofFilmPoint(const Vec3d& film, double wavelengthNm = kWavelengthDNm) const;

  double filmZ() const { return filmZ_; }
  // The largest field angle (deg) of the table: the chief rays of the open
  // lens at the d line reach that far.
  double tableFieldDeg() const;

 private:
  // One chief ray of the d line from infinity, in the meridional plane y = 0
  // with the object toward +x.
  struct Entry {
    double angle = 0.0;       // field angle from the axis (radians)
    double aimHeight = 0.0;   // its x on the entrance pupil's plane
    double axisZ = 0.0;       // where it crosses the axis in object space (entrance pupil of the field)
    double filmRadius = 0.0;  // -x where it meets the film (the image is inverted)
    double filmSlope = 0.0;   // dx/dz of its image-side ray
  };
  // Table values at a field angle and at a film radius (linear, clamped).
  Entry atAngle(double angle) const;
  Entry atFilmRadius(double radius) const;
  // Where the open lens's image-side ray meets the film, and whether the
  // real lens passes the whole ray.
  ChiefRayImage image(const LensRay& sceneRay, double wavelengthNm) const;
  // The same from a trace paused at the stop by open_, with its hits.
  ChiefRayImage imageFrom(const LensSystem::PausedTrace& paused, std::span<const Vec3d> hits,
                          double wavelengthNm) const;
  ChiefRayImage imageOf(const std::optional<LensRay>& rear, ChiefRayStatus status) const;

  LensSystem lens_;
  LensSystem open_;  // lens_ with its rims opened
  double filmZ_ = 0.0;
  double startZ_ = 0.0;  // in front of every surface: where rays from infinity start
  std::vector<Entry> table_;
};

}  // namespace lensrt
