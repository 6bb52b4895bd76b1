#include "camera/wavelength_lanes.h"

namespace lensrt {

std::array<float, 4> wavelengthLaneWeights(const std::array<LaneTrace, 4>& lanes) {
  std::array<float, 4> factors{};
  const LaneTrace& hero = lanes[0];
  if (!hero.counts || !(hero.density > 0.0) || !(hero.transmittance > 0.0)) return factors;
  double sum = 0.0;
  for (const LaneTrace& lane : lanes)
    if (lane.counts) sum += lane.density;
  const double scale = hero.density / (0.25 * sum) / hero.transmittance;
  for (std::size_t k = 0; k < lanes.size(); ++k)
    if (lanes[k].counts) factors[k] = float(lanes[k].transmittance * scale);
  return factors;
}

}  // namespace lensrt
