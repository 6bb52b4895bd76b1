// Spectral transport through a dispersive lens: the weights that let a path
// carry all four of its wavelengths past the lens, not its hero alone.
//
// A camera sample picks a film point in its pixel and a pupil point, and
// traces them at the hero wavelength; the ray that leaves the lens is the
// scene path's. At a secondary wavelength the same outgoing ray comes from
// another film point (lateral colour) through another pupil point. Each of
// the four wavelengths could have been the hero (the set is rotated, so the
// hero is any of them with probability 1/4) and would then have made this
// outgoing ray with its own density p_k; one-sample multiple importance
// sampling with the balance heuristic (Veach 1997; hero wavelength spectral
// sampling, Wilkie et al. 2014) weighs wavelength j's radiance by
//     T_j / ((1/4) sum_k p_k)
// against the hero's plain estimate T_h / p_h: lane j's factor is
//     (T_j / T_h) p_h / ((1/4) sum_k p_k).
// The densities are per unit of film area times projected solid angle at
// the film, in which every wavelength's trace measures the same outgoing
// ray alike (etendue is conserved through the lens, air on both sides): the
// Jacobian between the wavelengths' film densities is 1.
//
// Only the sample's own pixel counts (a box filter): a wavelength whose
// trace lands in another pixel has no density here (that pixel's own
// samples make it) and adds nothing, so no sample writes outside its pixel
// and the image stays the same whatever the tiles, threads or ranks. With
// every secondary outside, the hero's factor is 4 and the others 0: the
// plain hero-only estimate. A lane the lens blocks, or that leaves the exit
// pupil bounds its film point samples, has no density either.
#pragma once

#include <array>

namespace lensrt {

struct LaneTrace {
  bool counts = false;         // reaches the sample's pixel through the bounds it samples
  double density = 0.0;        // the hero's sampling density for that film point and ray (> 0 when counts)
  double transmittance = 0.0;  // the lens's (coatings, a mask) at the lane's wavelength
};

// lanes[0] is the hero, which counts. The factors on the hero's weight, per lane.
std::array<float, 4> wavelengthLaneWeights(const std::array<LaneTrace, 4>& lanes);

}  // namespace lensrt
