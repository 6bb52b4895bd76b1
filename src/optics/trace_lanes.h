// LensSystem's batched trace, a structure of arrays at a time: the step
// through a spherical surface for 8 rays in AVX registers (x86-64 CPUs that
// have AVX2; LensSystem falls back to its one-ray step elsewhere). The same
// IEEE operations in the same order as LensSystem::step, so every lane's
// result is bit-identical to tracing that ray alone (no FMA: contraction
// would change the rounding).
#pragma once

#include <array>
#include <cstddef>

namespace lensrt::trace_lanes {

inline constexpr std::size_t kLanes = 8;

struct Lanes {
  alignas(32) std::array<double, kLanes> ox{}, oy{}, oz{}, dx{}, dy{}, dz{};
  std::array<bool, kLanes> alive{};
};

// A spherical surface as the step needs it (see LensSystem::TraceSurface).
struct Sphere {
  double z = 0.0;
  double radius = 0.0;
  double absInvRadius = 0.0;
  double invRadius2 = 0.0;
  double apertureRadius2 = 0.0;
  double eta = 0.0;  // index ratio; 0 when the surface does not bend the ray
};

// True when this CPU runs sphereStep and the environment does not set
// LENSRT_DISABLE_AVX (checked once; the tests run both paths).
bool available();
// LensSystem::step<true> on every lane that is alive; dead lanes stay dead.
void sphereStep(const Sphere& s, Lanes& lanes);
// The same with each lane's own index ratio (its wavelength), 0 where the
// surface does not bend that lane's ray; s.eta is ignored.
void sphereStep(const Sphere& s, const std::array<double, kLanes>& eta, Lanes& lanes);

}  // namespace lensrt::trace_lanes
