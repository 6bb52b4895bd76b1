#include "optics/trace_lanes.h"

#include <cstring>

#include "core/cpu_features.h"
#include "optics/avx_doubles.h"

namespace lensrt::trace_lanes {

#if LENSRT_AVX_DOUBLES

namespace {

using namespace avx;

// Mirrors LensSystem::step<true> line by line; `ok` replaces its early returns.
// `etaLanes`: each lane's index ratio (0: that lane is not bent), or null for
// s.eta on every lane.
template <bool kRefracts>
LENSRT_AVX void step(const Sphere& s, const double* etaLanes, Lanes& L) {
  const V R = splat(s.radius), twoR = splat(2.0 * s.radius), zero = splat(0.0);
  for (std::size_t g = 0; g < kLanes; g += kWidth) {
    const M alive = loadMask(&L.alive[g]);
    if (none(alive)) continue;  // a blocked group, or lanes past the batch's end
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
    storeMask(&L.alive[g], alive & ok);
  }
}

// Mirrors the flat branch of LensSystem::step<true> with eta 0.
LENSRT_AVX void flatStep(const Sphere& s, Lanes& L) {
  const V zero = splat(0.0);
  for (std::size_t g = 0; g < kLanes; g += kWidth) {
    const M alive = loadMask(&L.alive[g]);
    if (none(alive)) continue;
    const V px = load(&L.ox[g]), py = load(&L.oy[g]), pz = load(&L.oz[g]) - splat(s.z);
    const V dx = load(&L.dx[g]), dy = load(&L.dy[g]), dz = load(&L.dz[g]);
    M ok = dz != zero;
    const V t = -pz / dz;
    ok &= t >= splat(-1e-9);
    const V hx = px + dx * t, hy = py + dy * t, hz = pz + dz * t;
    ok &= ~(hx * hx + hy * hy > splat(s.apertureRadius2));
    store(&L.ox[g], hx);
    store(&L.oy[g], hy);
    store(&L.oz[g], hz + splat(s.z));
    storeMask(&L.alive[g], alive & ok);
  }
}

// Mirrors validInput<true> and normalize() (start) or finished() (end):
// v / sqrt(v.x * v.x + v.y * v.y + v.z * v.z).
template <bool kStart>
LENSRT_AVX void startOrFinish(Lanes& L) {
  const V zero = splat(0.0);
  for (std::size_t g = 0; g < kLanes; g += kWidth) {
    const M alive = loadMask(&L.alive[g]);
    if (none(alive)) continue;
    const V dx = load(&L.dx[g]), dy = load(&L.dy[g]), dz = load(&L.dz[g]);
    M ok = finite(load(&L.ox[g])) & finite(load(&L.oy[g])) & finite(load(&L.oz[g])) & finite(dx) &
           finite(dy) & finite(dz);
    if constexpr (kStart) ok &= dz < zero;
    const V len = sqrt(dx * dx + dy * dy + dz * dz);
    store(&L.dx[g], dx / len);
    store(&L.dy[g], dy / len);
    store(&L.dz[g], dz / len);
    storeMask(&L.alive[g], alive & ok);
  }
}

}  // namespace

bool available() {
  return avx2Enabled();
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

void planeStep(const Sphere& s, Lanes& lanes) {
  flatStep(s, lanes);
}

void start(Lanes& lanes) {
  startOrFinish<true>(lanes);
}

void finish(Lanes& lanes) {
  startOrFinish<false>(lanes);
}

#else

bool available() {
  return false;
}
void sphereStep(const Sphere&, Lanes&) {}
void sphereStep(const Sphere&, const std::array<double, kLanes>&, Lanes&) {}
void planeStep(const Sphere&, Lanes&) {}
void start(Lanes&) {}
void finish(Lanes&) {}

#endif

}  // namespace lensrt::trace_lanes
