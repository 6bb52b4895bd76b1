// The projection of a camera model: where a point images on the film, and
// the ray a film position sees. Labels that must match the image pixel for
// pixel (optical flow, calibration) come from it.
//
// A point maps to where its chief ray meets the film: the ray from it through
// the centre of the aperture stop (the full lens, traced exactly:
// optics/chief_ray.h), through the lens's centre (thin), through the centre
// of the entrance pupil and, by the paraxial rules, of the exit pupil
// (thick), through the pinhole. That is the centre of the point's blur spot
// as the stop closes, so it holds whatever the focus, and it is what OpenCV's
// and COLMAP's camera models describe.
//
// Conventions (as the rendering's, camera/camera.h):
//  - camera space: glTF's, metres, looking down -Z with +Y up; the origin is
//    the entrance pupil's centre (the lens's centre for thin, the pinhole);
//  - raster: pixels, (0, 0) the top-left corner of the top-left pixel, x
//    right and y down, so pixel (i, j)'s centre is (i + 0.5, j + 0.5);
//  - wavelengths in nm: the full lens and a thick lens with dispersion data
//    image each wavelength at its own place (lateral colour); the others
//    ignore it.
// Every model's projection is const, thread-safe and deterministic: a
// renderer may call it for every sample.
#pragma once

#include <cstdint>

#include "core/vec.h"

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
