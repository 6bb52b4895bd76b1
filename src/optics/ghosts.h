// The two-reflection ghosts of a lens (stray light): light that reflects at a
// surface `first` back toward the scene, then at a surface `second` in front
// of it forward again, and reaches the film out of focus. Paraxial analysis
// of each pair, on axis, for a point at infinity: where the ghost focuses,
// how large it is on the film, how strong it is (R_first R_second at normal
// incidence) and how much of its bundle the apertures let through.
//
// Traced by ray slopes u = dy/dz, which refraction and reflection change by
// the same rules whichever way the ray travels along z:
//   refraction (n1 -> n2, curvature c): n2 u' = n1 u - y c (n2 - n1),
//   reflection:                         u' = -u - 2 c y,
// and a ray goes from z_a to z_b as y_b = y_a + u (z_b - z_a).
#pragma once

#include <optional>
#include <vector>

#include "optics/coating.h"
#include "optics/prescription.h"

namespace lensrt {

struct GhostPath {
  int first = 0;   // surface reflecting first (0-based, nearer the film)
  int second = 0;  // surface reflecting second (nearer the scene): second < first
  // R_first R_second at normal incidence and 550 nm, with the lens's coating.
  double strength = 0.0;
  // Of a bundle filling the front element's clear aperture, the part that
  // reaches the film within every aperture it crosses, over the direct
  // image's bundle (the entrance pupil): the ghost's flux is strength x this
  // times the direct image's.
  double passing = 0.0;
  // The ghost's paraxial focus from the film plane (the rear focal point,
  // where a point at infinity focuses): + behind the film; none when the
  // ghost leaves parallel (afocal).
  std::optional<double> focusFromFilmMm;
  double sizeOnFilmMm = 0.0;  // diameter of the passing bundle on the film
};

// Every pair of reflecting surfaces (where the index changes: not the stop)
// in the order of the prescription; `coating` as in optics/coating.h (none:
// bare glass). Throws std::domain_error for an afocal lens.
std::vector<GhostPath> ghostPaths(const LensPrescription& lens, Coating coating);

// The same sorted by strength, strongest first (ties: by passing flux).
std::vector<GhostPath> strongestGhosts(const LensPrescription& lens, Coating coating);

}  // namespace lensrt
