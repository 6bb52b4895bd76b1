// The sensor's readout (api/sensor_readout.h): noise and the ADC.
#pragma once

#include <string>

namespace lensrt {

struct SensorSpec {
  bool noise = false;
  std::string params;  // a preset or a .json file; empty: the default sensor
};

}  // namespace lensrt
