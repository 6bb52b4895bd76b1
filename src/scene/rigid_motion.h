// A rigid node's placement at each motion step as Embree's quaternion
// decomposition (p' = T R S p): Embree slerps R between steps, so a turning
// node sweeps true arcs about its origin, and its mesh is stored once instead
// of once per step.
#pragma once

#include <embree3/rtcore.h>

#include <optional>
#include <vector>

#include "core/transform.h"

namespace lensrt {

// The affine `xf` as a rotation R (a quaternion) times an upper triangular
// scale and skew S (a QR decomposition of its linear part; a mirror stays in
// S as a negative scale_z), then its translation. None when the linear part
// is singular.
std::optional<RTCQuaternionDecomposition> quaternionDecomposition(const Transform& xf);

// One decomposition per step; each quaternion's sign is chosen next to the
// step before it, so that the slerp between them takes the short way.
// None when any step is singular.
std::optional<std::vector<RTCQuaternionDecomposition>> rigidMotionSteps(const std::vector<Transform>& steps);

}  // namespace lensrt
