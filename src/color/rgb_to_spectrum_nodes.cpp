#include "color/rgb_to_spectrum.h"

namespace lensrt {

// Shared by the generator and the library, which share no other code.
double rgbToSpectrumNode(int k, int resolution) {
  const auto smoothstep = [](double x) { return x * x * (3.0 - 2.0 * x); };
  return smoothstep(smoothstep(k / double(resolution - 1)));
}

}  // namespace lensrt
