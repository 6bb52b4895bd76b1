#pragma once

#include <cmath>

#include "core/vec.h"

namespace lensrt {

// Orthonormal basis around a unit normal (Duff et al. 2017, branchless).
struct Frame {
  Vec3f s, t, n;

  static Frame fromNormal(const Vec3f& n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    return {{1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
  }
  Vec3f toLocal(const Vec3f& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3f toWorld(const Vec3f& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace lensrt
