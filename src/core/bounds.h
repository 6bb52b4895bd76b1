#pragma once

#include "core/constants.h"
#include "core/vec.h"

namespace lensrt {

struct Bounds3f {
  Vec3f lo{kInfinityF, kInfinityF, kInfinityF};
  Vec3f hi{-kInfinityF, -kInfinityF, -kInfinityF};

  bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  void extend(const Vec3f& p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void extend(const Bounds3f& b) {
    lo = min(lo, b.lo);
    hi = max(hi, b.hi);
  }
  Vec3f center() const { return (lo + hi) * 0.5f; }
  Vec3f diagonal() const { return hi - lo; }
};

}  // namespace lensrt
