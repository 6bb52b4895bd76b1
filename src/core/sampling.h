// Warps of the unit square that samplers' points go through.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/vec.h"

namespace lensrt {

// Shirley and Chiu's concentric map of [0,1)^2 onto the unit disk: area
// preserving and continuous, so a stratified point set stays stratified.
// Shared by the BSDFs' cosine hemisphere and the thin and thick lenses'
// round apertures; in float, whose single sincosf costs a third of double's.
inline Vec2f concentricDisk(const Vec2f& u) {
  const float a = 2 * u.x - 1, b = 2 * u.y - 1;
  float r = 0, phi = 0;
  if (a != 0 || b != 0) {
    if (std::abs(a) > std::abs(b)) {
      r = a;
      phi = (kPiF / 4) * (b / a);
    } else {
      r = b;
      phi = kPiF / 2 - (kPiF / 4) * (a / b);
    }
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

}  // namespace lensrt
