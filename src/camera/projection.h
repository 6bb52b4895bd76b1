// The projection of a camera model: where a point images on the film, and
// the ray a film position sees. Labels that must match the image pixel for
// pixel (optical flow, calibration) come from it.
//
// Design notes: docs/design/projection.md.
#pragma once

#include <cstdint>

#include "core/vec.h"
#include "optics/chief_ray_hint.h"

namespace lensrt {

enum class Visibility : std::uint8_t {
  Visible = 0,       // the chief ray reaches the film inside the frame
  OutsideFrame = 1,  // it reaches the film plane outside the frame (raster outside [0, W] x [0, H])
  Blocked = 2,       // the lens stops it (a rim, or no ray through the stop's centre)
  Behind = 3,        // the point is not in front of the camera (raster is NaN)
};

// A point's image in raster pixels. Blocked: where the full lens's chief ray
// would meet the film with the rims opened, NaN when there is no such ray.
struct ProjectedPoint {
  Vec2d raster;
  Visibility visibility = Visibility::Behind;
};

// The chief ray a raster position sees, toward the scene (unit direction):
// for the full lens where it leaves the front glass, for the others from the
// camera origin. Visibility as above (never Behind); NaN when Blocked with
// no ray.
struct ProjectedRay {
  Vec3d origin;
  Vec3d direction;
  Visibility visibility = Visibility::Blocked;
};

}  // namespace lensrt
