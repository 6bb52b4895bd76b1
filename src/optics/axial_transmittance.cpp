#include "optics/axial_transmittance.h"

#include <algorithm>

namespace lensrt {

double axialTransmittance(const LensSystem& lens, int grid) {
  // The bundle is as wide as the entrance pupil; a margin over the paraxial
  // pupil covers its aberrated edge, the front aperture bounds it, and the
  // trace (the stop) decides which rays belong to it.
  const Surface& front = lens.prescription().surfaces.front();
  const double a = std::min(front.apertureDiameter / 2.0, 0.65 * lens.paraxial().entrancePupilDiameter);
  const double z = front.minSag() - 1.0;
  double sum = 0.0;
  int passed = 0;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const double x = a * (2.0 * (i + 0.5) / grid - 1.0), y = a * (2.0 * (j + 0.5) / grid - 1.0);
      if (x * x + y * y > a * a) continue;
      const auto out = lens.traceFromScene({{x, y, z}, {0.0, 0.0, 1.0}});
      if (!out) continue;
      sum += out->transmittance;
      ++passed;
    }
  return passed > 0 ? sum / passed : 0.0;
}

}  // namespace lensrt
