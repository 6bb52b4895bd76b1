#include "optics/trace_lanes.h"

#include <cstdlib>
#include <cstring>

namespace lensrt::trace_lanes {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))

namespace {

// GCC/clang vector extensions: four doubles, and the all-ones/zero masks
// their comparisons give.
using V = double __attribute__((vector_size(32)));
using M = long long __attribute__((vector_size(32)));
constexpr std::size_t kWidth = 4;

#define LENSRT_AVX __attribute__((target("avx2")))

LENSRT_AVX inline V splat(double x) {
  return V{x, x, x, x};
}
LENSRT_AVX inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
LENSRT_AVX inline void store(double* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
// m ? a : b, lane by lane.
LENSRT_AVX inline V select(M m, V a, V b) {
  return (V)(((M)a & m) | ((M)b & ~m));
}
LENSRT_AVX inline V sqrt(V v) {
  return __builtin_ia32_sqrtpd256(v);
}

// Mirrors LensSystem::step<true> line by line; `ok` replaces its early returns.
// `etaLanes`: each lane's index ratio (0: that lane is not bent), or null for
// s.eta on every lane.
template <bool kRefracts>
LENSRT_AVX void step(const Sphere& s, const double* etaLanes, Lanes& L) {
  const V R = splat(s.radius), twoR = splat(2.0 * s.radius), zero = splat(0.0);
  for (std::size_t g = 0; g < kLanes; g += kWidth) {
    const V px = load(&L.ox[g]), py = load(&L.oy[g]), pz = load(&L.oz[g]) - splat(s.z);
    const V dx = load(&L.dx[g]), dy = load(&L.dy[g]), dz = load(&L.dz[g]);
    const V zc = pz - R;
    const V b = px * dx + py * dy + zc * dz;
    const V c = px * px + py * py + pz * (pz - twoR);
    const V disc = b * b - c;
    M ok = disc >= zero;
    const V root = sqrt(select(ok, disc, zero));
    const V tNear = -b - root, tFar = -b + root;
    const M near = (tNear >= splat(-1e-9)) & ((zc + dz * tNear) * R < zero);
    const M far = (tFar >= splat(-1e-9)) & ((zc + dz * tFar) * R < zero);
    ok &= near | far;
    const V t = select(near, tNear, tFar);
    const V hx = px + dx * t, hy = py + dy * t, hz = pz + dz * t;
    ok &= ~(hx * hx + hy * hy > splat(s.apertureRadius2));
    store(&L.ox[g], hx);
    store(&L.oy[g], hy);
    store(&L.oz[g], hz + splat(s.z));
    V dzOut = dz;
    if constexpr (kRefracts) {
      const V eta = etaLanes ? load(&etaLanes[g]) : splat(s.eta), one = splat(1.0);
      const M bends = eta != zero;  // a lane with eta 0 only crosses the surface
      const V normalScale = select(near, splat(s.absInvRadius), splat(-s.absInvRadius));
      const V scaledDisc = disc * splat(s.invRadius2);
      const V cos2I = select(scaledDisc < one, scaledDisc, one);  // std::min(1.0, scaledDisc)
      const V sin2T = eta * eta * (one - cos2I);
      ok &= ~(bends & (sin2T >= one));
      const V cosI = root * splat(s.absInvRadius);
      const V cosT = sqrt(select(ok & bends, one - sin2T, zero));
      const V k = normalScale * (eta * cosI - cosT);
      store(&L.dx[g], select(bends, dx * eta + hx * k, dx));
      store(&L.dy[g], select(bends, dy * eta + hy * k, dy));
      dzOut = select(bends, dz * eta + (hz - R) * k, dz);
      store(&L.dz[g], dzOut);
    }
    ok &= dzOut < zero;
    for (std::size_t l = 0; l < kWidth; ++l) L.alive[g + l] = L.alive[g + l] && ok[l] != 0;
  }
}

}  // namespace

bool available() {
  static const bool avx2 = __builtin_cpu_supports("avx2") && !std::getenv("LENSRT_DISABLE_AVX");
  return avx2;
}

void sphereStep(const Sphere& s, Lanes& lanes) {
  if (s.eta != 0.0)
    step<true>(s, nullptr, lanes);
  else
    step<false>(s, nullptr, lanes);
}

void sphereStep(const Sphere& s, const std::array<double, kLanes>& eta, Lanes& lanes) {
  step<true>(s, eta.data(), lanes);
}

#else

bool available() {
  return false;
}
void sphereStep(const Sphere&, Lanes&) {}
void sphereStep(const Sphere&, const std::array<double, kLanes>&, Lanes&) {}

#endif

}  // namespace lensrt::trace_lanes
