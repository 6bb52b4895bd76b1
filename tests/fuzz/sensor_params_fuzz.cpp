// libFuzzer target for --sensor-params FILE.json: the bytes through the
// sensor reader, then a readout of a few values with what it accepted. Only
// InputError may escape; accepted parameters describe a sensor
// (sensorParamsProblem is empty) and read out finite DN inside the ADC's range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.h"
#include "fuzz/fuzz_check.h"
#include "sensor/readout.h"
#include "sensor/sensor_params.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace lensrt;
  try {
    const SensorParams p =
        parseSensorParams(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
    LENSRT_FUZZ_CHECK(sensorParamsProblem(p).empty());
    const SensorExposure e = normalizedSensorExposure(p, 0.01);
    for (const double value : {0.0, 1e-3, 0.5, 1.0, 4.0}) {
      const double dn = readoutDn(p, e, value, 3, 5, 1, 7);
      LENSRT_FUZZ_CHECK(std::isfinite(dn) && dn >= 0.0 && dn <= p.maxDn());
    }
  } catch (const InputError&) {
  }
  return 0;
}
