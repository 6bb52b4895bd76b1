#include "camera/exposure.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/constants.h"

namespace lensrt {

double idealIrradianceRatio(double fNumber) {
  return kPi / (4.0 * fNumber * fNumber);
}

double exposureScale(const Exposure& exposure, double fNumber) {
  if (!(fNumber > 0.0) || !std::isfinite(fNumber)) throw std::invalid_argument("f-number must be positive");
  if (exposure.mode == ExposureMode::Normalized) return 1.0 / idealIrradianceRatio(fNumber);
  if (!(exposure.shutterSeconds > 0.0) || !(exposure.iso > 0.0))
    throw std::invalid_argument("shutter time and ISO must be positive");
  return kLuminousEfficacy * exposure.shutterSeconds * exposure.iso / kIsoSaturationConstant;
}

std::string describe(const Exposure& exposure) {
  if (exposure.mode == ExposureMode::Normalized) return "normalized";
  char buf[96];
  std::snprintf(buf, sizeof buf, "physical %gs ISO%g", exposure.shutterSeconds, exposure.iso);
  return buf;
}

}  // namespace lensrt
