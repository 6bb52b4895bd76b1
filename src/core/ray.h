#pragma once

#include "core/constants.h"
#include "core/vec.h"

namespace lensrt {

// A world-space ray for the scene. Directions need not be unit length unless a
// consumer says so; t is measured in units of |d|.
struct Ray {
  Vec3f origin;
  Vec3f direction;
  float tMin = 0.0f;
  float tMax = kInfinityF;
  // When the ray travels, as a fraction of the span the scene was loaded
  // for (its motion steps, MeshInstance::motion): 0 at the start.
  float time = 0.0f;
};

}  // namespace lensrt
