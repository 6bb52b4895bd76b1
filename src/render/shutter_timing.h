// When each camera sample is taken: within the shutter interval, after the
// delay of its row (or column) under a rolling shutter, as a fraction of
// the span the scene was loaded for (the shutter plus the readout; the
// motion steps of scene_desc.h cover it). Rendering gives rays this time,
// and Embree places moving meshes at it.
#pragma once

#include <string>
#include <vector>

#include "core/ray.h"
#include "core/transform.h"
#include "core/vec.h"

namespace lensrt {

struct ShutterTiming {
  double shutterSeconds = 0.0;  // each row's exposure
  double readoutSeconds = 0.0;  // rolling shutter: the last row starts this much after the first; 0: global
  enum class Readout { TopDown, BottomUp, LeftRight, RightLeft };
  Readout readout = Readout::TopDown;  // in the image as seen
  // A leaf shutter's ramps: the fraction of the interval it takes to open
  // (and again to close), the transmission rising and falling linearly; 0: a
  // box (instant opening).
  double rampFraction = 0.0;
  // The camera's own motion over the span, as world-to-world transforms
  // from its pose at the opening to its pose at evenly spaced steps (the
  // first the identity); empty: the camera is still. A camera ray is moved
  // by these interpolated linearly at its time, as Embree moves geometry.
  std::vector<Transform> cameraSteps;

  double spanSeconds() const { return shutterSeconds + readoutSeconds; }
  // The time, in [0, 1] of the span, of a sample at raster position `film`
  // (pixels, continuous) of a width x height frame, from a uniform `u`.
  float sampleTime(const Vec2f& film, int width, int height, float u) const;
  // `ray` (made at the opening pose) moved with the camera to its time.
  Ray moveWithCamera(const Ray& ray) const;
  // "box 0.01 s", "trapezoid:0.2 0.01 s, rolling top-down 0.03 s": for the metadata.
  std::string describe() const;
};

// Where in the shutter interval, in [0, 1], a uniform u falls under a
// trapezoid of ramps `ramp` (0 <= ramp <= 0.5; 0: u itself): the inverse of
// its normalised cumulative opening.
double shutterCurveInverse(double u, double ramp);

}  // namespace lensrt
