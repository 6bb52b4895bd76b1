#include "optics/trace_lanes.h"

#include <cstring>

#include "core/cpu_features.h"
#include "optics/avx_doubles.h"

namespace lensrt::trace_lanes {

#if LENSRT_AVX_DOUBLES

namespace {

// The kernels (trace_lanes_kernels.inc), compiled for AVX2's four doubles and
// for AVX-512's eight: the same operations lane by lane, so the same bits
// (kLanes holds whole groups of either width).
static_assert(kLanes % avx::kWidth == 0 && kLanes % avx512::kWidth == 0);

namespace four {
using namespace avx;
#define LENSRT_LANES_TARGET LENSRT_AVX
#include "optics/trace_lanes_kernels.inc"
#undef LENSRT_LANES_TARGET
}  // namespace four

namespace eight {
using namespace avx512;
#define LENSRT_LANES_TARGET LENSRT_AVX512
#include "optics/trace_lanes_kernels.inc"
#undef LENSRT_LANES_TARGET
}  // namespace eight

}  // namespace

bool available() {
  return avx2Enabled();
}

void sphereStep(const Sphere& s, Lanes& lanes) {
  if (avx512Enabled())
    s.eta != 0.0 ? eight::step<true>(s, nullptr, lanes) : eight::step<false>(s, nullptr, lanes);
  else
    s.eta != 0.0 ? four::step<true>(s, nullptr, lanes) : four::step<false>(s, nullptr, lanes);
}

void sphereStep(const Sphere& s, const std::array<double, kLanes>& eta, Lanes& lanes) {
  avx512Enabled() ? eight::step<true>(s, eta.data(), lanes) : four::step<true>(s, eta.data(), lanes);
}

void planeStep(const Sphere& s, Lanes& lanes) {
  avx512Enabled() ? eight::flatStep(s, lanes) : four::flatStep(s, lanes);
}

void start(Lanes& lanes) {
  avx512Enabled() ? eight::startOrFinish<true>(lanes) : four::startOrFinish<true>(lanes);
}

void finish(Lanes& lanes) {
  avx512Enabled() ? eight::startOrFinish<false>(lanes) : four::startOrFinish<false>(lanes);
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
