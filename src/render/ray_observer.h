// An opt-in view of every ray the integrator traces, for measuring
// instruments (tools/bench records a pass's rays and traces them with Embree
// alone). Off (a null pointer in IntegratorSettings) it costs one predictable
// branch per ray; the renderer itself never sets it.
#pragma once

#include <cstdint>

#include "core/ray.h"

namespace lensrt {

enum class RayKind : std::uint8_t {
  Camera,  // the first ray of a path (from the camera into the scene)
  Bounce,  // continuing a path after BSDF sampling
  Shadow,  // next-event estimation: an occlusion query toward a light
};

class RayObserver {
 public:
  virtual ~RayObserver() = default;
  // Called from every render thread at once, just before the ray is traced.
  virtual void traced(RayKind kind, const Ray& ray) = 0;
};

}  // namespace lensrt
