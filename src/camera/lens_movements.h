// Lens movements: the film shifted in its plane and tilted against the lens,
// as a view camera's rear standard (or a tilt-shift lens) moves it. The
// thin, thick and full-lens models take both, the pinhole the shift alone;
// docs/lens-movements.md has the conventions with pictures in words.
#pragma once

#include <optional>
#include <string>

#include "core/vec.h"

namespace lensrt {

struct FilmGeometry;

// Conventions (upright picture coordinates: x right, y up, as the picture is
// seen; the lens, where the camera points, never moves):
//  - shiftMm (X, Y): the frame moves by (X, Y) mm across the image the lens
//    forms, so its centre shows what an unshifted film showed at (X, Y) mm
//    from its centre: +Y shows more of the scene above (architecture's
//    rising front: the lens raised against the film), +X more to the right.
//    A distant point's image moves by -(X, Y) mm within the frame.
//  - tiltDegrees: the film turns by this angle about a line in its plane
//    through the point where the optical axis meets it (the focus stays
//    where the plane of focus crosses the axis). tiltAxisDegrees is that
//    line's direction, counter-clockwise from the picture's x axis: 0 turns
//    the film about a horizontal line (a tilt), 90 about a vertical one (a
//    swing). A positive tilt takes the film's side that holds the bottom of
//    the picture (axis 0; its right side at axis 90) away from the lens, so
//    the plane of sharp focus swings down toward the ground (toward the
//    right at 90): the Scheimpflug rule's plane, which meets the lens plane
//    where the film plane does, and passes the hinge line at
//    J = f / sin(tilt) from the lens (the front principal point), in the
//    plane through the lens parallel to the film.
//    This is a view camera's back tilt: the film no longer square to the
//    lens also stretches the picture a little (1 / cos(tilt) at most). A
//    tilt-shift lens's front tilt is the same relative tilt with the whole
//    camera turned by the tilt.
struct LensMovements {
  Vec2d shiftMm{};
  double tiltDegrees = 0.0;
  double tiltAxisDegrees = 0.0;

  bool shifted() const { return shiftMm.x != 0.0 || shiftMm.y != 0.0; }
  bool tilted() const { return tiltDegrees != 0.0; }
  bool any() const { return shifted() || tilted(); }
  // For a camera's describe() (part of the render's identity): empty
  // without movements, else e.g. " shift=0,8mm tilt=4deg" or
  // " tilt=4deg tilt-axis=90deg" (leading space; the axis only when tilted
  // and not 0).
  std::string describe() const;
};

// The limits, inclusive:
inline constexpr double kMaxTiltDegrees = 30.0;       // more than tilt-shift lenses (8-15 deg) give
inline constexpr double kMaxTiltAxisDegrees = 360.0;  // |axis|, as --blade-rotation
// |shift X| <= the sensor's width and |shift Y| <= its height: a frame moved
// farther has left the original frame entirely, beyond any lens's image
// circle's use (real shifts: 10-15 mm on 36x24).

// What is wrong with the movements for this film, as a sentence naming the
// value and the limit (nullopt: nothing). The caller prefixes the flag or
// keyword. Messages:
//  "the shift's X (40 mm) must lie within +-36 mm (the sensor's width)"
//  "the shift's Y (-30 mm) must lie within +-24 mm (the sensor's height)"
//  "the tilt (35 degrees) must lie within +-30 degrees"
//  "the tilt axis (400 degrees) must lie within +-360 degrees"
//  "the shift must be finite" (NaN or infinite X or Y; likewise tilt, axis)
std::optional<std::string> lensMovementsProblem(const LensMovements& m, const FilmGeometry& film);
// Throws std::invalid_argument("<model>: <problem>") when there is one; a
// camera's constructor calls it.
void checkLensMovements(const LensMovements& m, const FilmGeometry& film, const char* model);

// The film as the movements place it behind the lens: where each upright
// sensor point lies, relative to the point where the optical axis meets
// the film (the pivot). Coordinates are lens space and camera space alike
// (mm; x, y as camera space's; +z from the lens toward the film): the
// physical film holds the inverted image, so an upright point (x, y) of
// the unmoved film lies at (-x, -y, 0).
class MovedFilm {
 public:
  explicit MovedFilm(const LensMovements& m);

  // The film point of an upright sensor point (mm from the frame's centre),
  // relative to the pivot.
  Vec3d offset(Vec2d upright) const;
  // The upright sensor point of a point on the moved film plane (relative
  // to the pivot): offset()'s inverse.
  Vec2d upright(const Vec3d& offset) const;
  // The film's unit normal, toward the lens ((0, 0, -1) untilted).
  const Vec3d& normal() const { return normal_; }
  // Over the frame of `film` (its four corners, since both are linear or
  // convex in the position): the largest distance of a film point from the
  // axis, and the range of its offset along z.
  double maxRadius(const FilmGeometry& film) const;
  struct DepthRange {
    double min = 0.0, max = 0.0;
  };
  DepthRange depthRange(const FilmGeometry& film) const;
  // Where a film-side line meets the moved film, as an upright sensor point
  // (mm): the line crosses the unmoved film's plane (the pivot's, z toward
  // the film) at `at` and moves by `slope` (dx/dz, dy/dz) along z. nullopt
  // when it runs along the film. The projections of moved films use it.
  std::optional<Vec2d> uprightOfLine(const Vec2d& at, const Vec2d& slope) const;

 private:
  Vec2d shift_;
  Vec2d axis_{1.0, 0.0};    // the tilt axis, upright
  Vec2d across_{0.0, 1.0};  // perpendicular to it in the film plane, upright
  double cosTilt_ = 1.0, sinTilt_ = 0.0;
  Vec3d normal_{0.0, 0.0, -1.0};
};

}  // namespace lensrt
