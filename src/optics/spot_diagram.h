// Spot diagrams: where the rays of one field point land on the film.
//
// Rays are spread uniformly over the part of the aim plane (z = 0, see
// distortion.h) that passes the lens, on a square grid, so each ray stands
// for an equal area of the incoming beam (exactly, for an object at
// infinity). The RMS radius is about the spot's centroid.
#pragma once

#include <vector>

#include "core/vec.h"
#include "optics/distortion.h"
#include "optics/glass.h"
#include "optics/lens_system.h"

namespace lensrt {

struct SpotDiagram {
  FieldPoint field;
  std::vector<Vec2d> points;  // film (x, y), mm, lens space
  Vec2d centroid;             // mm
  double rmsRadiusMm = 0.0;   // sqrt(mean |p - centroid|^2)
  double maxRadiusMm = 0.0;   // from the centroid
  int traced = 0;             // rays tried inside the pass bounds
};

// `grid` rays across the widest extent of the passing beam (about
// pi/4 grid^2 pass on the axis). An empty spot when nothing passes.
SpotDiagram spotDiagram(const LensSystem& lens, const FieldPoint& field, double filmDistanceMm, int grid = 41,
                        double wavelengthNm = kWavelengthDNm);

}  // namespace lensrt
