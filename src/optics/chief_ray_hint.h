// Where a chief-ray solve may start (optics/chief_ray.h): what the solve of
// a nearby point learnt. A pixel's flow samples see points a fraction of a
// millimetre apart, and each solve started from the last one's takes fewer
// traces through the lens than one started from the table of chief rays.
#pragma once

#include <cmath>
#include <limits>

namespace lensrt {

// A start only: a solve converges to the same tolerance from it, so the
// image moves by rounding alone; the bits then depend on the hint, so a
// caller that must give the same bits passes the same hints. Floats: a
// start needs no more, and a pixel carries one (render/motion_flow.h).
struct ChiefRayHint {
  // Where the last chief ray crossed the axis (lens space, mm), and how far
  // from the crossing of the table's chief ray from infinity at its field
  // angle: the crossing moves with the field as the table's does, and that
  // offset (the pupil's aberration at the point's distance) moves slowly.
  float axisZ = std::numeric_limits<float>::quiet_NaN();
  float axisOffset = 0.0f;
  // The rate of its stop height with its slope, per mm from that crossing.
  float heightPerSlope = 0.0f;
  bool valid() const {
    return std::isfinite(axisZ) && std::isfinite(heightPerSlope) && heightPerSlope != 0.0f;
  }
};

}  // namespace lensrt
