// Raster pixels to sensor millimetres, shared by every model so they agree on
// orientation.
#pragma once

#include <cmath>

#include "camera/camera.h"
#include "core/vec.h"

namespace lensrt {

// The sensor point (mm, relative to the sensor centre) where the UPRIGHT image
// of raster position `raster` lies: x right, y up, as the picture is seen.
// A lens forms an inverted image, so the physical film point behind the lens
// is the negative of this (the camera reads the sensor out rotated by 180 deg).
inline Vec2d uprightSensorPointMm(const FilmGeometry& f, const Vec2f& raster) {
  return {(double(raster.x) / f.width - 0.5) * f.sensorWidthMm,
          (0.5 - double(raster.y) / f.height) * f.sensorHeightMm};
}

// The same for a raster position in double precision (the projections').
inline Vec2d uprightSensorPointOfRaster(const FilmGeometry& f, const Vec2d& raster) {
  return {(raster.x / f.width - 0.5) * f.sensorWidthMm, (0.5 - raster.y / f.height) * f.sensorHeightMm};
}

// The raster position of an upright sensor point: the inverse of the above.
inline Vec2d rasterOfUprightSensorPointMm(const FilmGeometry& f, const Vec2d& mm) {
  return {(mm.x / f.sensorWidthMm + 0.5) * f.width, (0.5 - mm.y / f.sensorHeightMm) * f.height};
}

// A projected position's place in the frame (camera/projection.h): inside
// [0, W] x [0, H] or not.
inline Visibility frameVisibility(const FilmGeometry& f, const Vec2d& raster) {
  return raster.x >= 0.0 && raster.x <= f.width && raster.y >= 0.0 && raster.y <= f.height
             ? Visibility::Visible
             : Visibility::OutsideFrame;
}

inline double sensorHalfDiagonalMm(const FilmGeometry& f) {
  return 0.5 * std::hypot(f.sensorWidthMm, f.sensorHeightMm);
}

// cos^4 of the angle to the axis of a ray from a film point offset (x, y)
// (mm) to a pupil point straight ahead at axial distance `dz`: the natural
// vignetting of an ideal lens, without hypot or a square root (a camera ray's
// cost).
inline double cos4ToAxis(double x, double y, double dz) {
  const double c2 = dz * dz / (dz * dz + x * x + y * y);
  return c2 * c2;
}

}  // namespace lensrt
