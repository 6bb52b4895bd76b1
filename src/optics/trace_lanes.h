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

// Thirty-two rays in flight: a surface's step is a chain of dependent square
// roots, and eight groups of four independent chains keep the vector units
// busy where two left them waiting on latency.
inline constexpr std::size_t kLanes = 32;

struct Lanes {
  alignas(32) std::array<double, kLanes> ox{}, oy{}, oz{}, dx{}, dy{}, dz{};
  // All ones while the ray is alive, 0 once blocked: the comparisons' own
  // masks, so the steps combine them without converting.
  alignas(32) std::array<long long, kLanes> alive{};
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
// LensSystem::step<true> through a flat surface that does not bend the ray
// (the stop), on every lane that is alive.
void planeStep(const Sphere& s, Lanes& lanes);
// The start of LensSystem's trace on every lane that is alive: those whose
// origin or direction is not finite, or whose direction does not point
// toward the scene (dz >= 0), die; the others' directions are normalised.
void start(Lanes& lanes);
// The end of the trace (LensSystem's finished()): lanes whose origin or
// direction is not finite die, the others' directions are normalised.
void finish(Lanes& lanes);

}  // namespace lensrt::trace_lanes
