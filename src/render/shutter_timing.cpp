#include "render/shutter_timing.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace lensrt {

double shutterCurveInverse(double u, double ramp) {
  if (!(ramp > 0)) return u;
  // Transmission rises over [0, F], stays 1, falls over [1 - F, 1]: its
  // integral is 1 - F; c is the share of it before the sample.
  const double f = std::min(ramp, 0.5);
  const double c = u * (1.0 - f);
  if (c < f / 2) return std::sqrt(2.0 * f * c);
  if (c <= 1.0 - 1.5 * f) return c + f / 2;
  return 1.0 - std::sqrt(std::max(0.0, 2.0 * f * (1.0 - f - c)));
}

float ShutterTiming::sampleTime(const Vec2f& film, int width, int height, float u) const {
  const double span = spanSeconds();
  if (!(span > 0)) return 0.0f;
  double delay = 0;
  if (readoutSeconds > 0) {
    const double across = readout == Readout::TopDown || readout == Readout::BottomUp
                              ? double(film.y) / double(std::max(1, height))
                              : double(film.x) / double(std::max(1, width));
    const bool reversed = readout == Readout::BottomUp || readout == Readout::RightLeft;
    delay = readoutSeconds * std::clamp(reversed ? 1.0 - across : across, 0.0, 1.0);
  }
  const double t = (delay + shutterSeconds * shutterCurveInverse(double(u), rampFraction)) / span;
  return float(std::clamp(t, 0.0, 1.0));
}

Ray ShutterTiming::moveWithCamera(const Ray& ray) const {
  if (cameraSteps.size() < 2) return ray;
  const float f = std::clamp(ray.time, 0.0f, 1.0f) * float(cameraSteps.size() - 1);
  const std::size_t k = std::min(static_cast<std::size_t>(f), cameraSteps.size() - 2);
  const float a = f - float(k);
  const Transform &m0 = cameraSteps[k], &m1 = cameraSteps[k + 1];
  Ray moved = ray;
  moved.origin = m0.point(ray.origin) * (1 - a) + m1.point(ray.origin) * a;
  moved.direction = normalize(m0.vector(ray.direction) * (1 - a) + m1.vector(ray.direction) * a);
  return moved;
}

std::string ShutterTiming::describe() const {
  std::string s = rampFraction > 0 ? fmt::format("trapezoid:{:g} {:g} s", rampFraction, shutterSeconds)
                                   : fmt::format("box {:g} s", shutterSeconds);
  if (readoutSeconds > 0) {
    static constexpr const char* kNames[] = {"top-down", "bottom-up", "left-right", "right-left"};
    s += fmt::format(", rolling {} {:g} s", kNames[static_cast<int>(readout)], readoutSeconds);
  }
  return s;
}

}  // namespace lensrt
