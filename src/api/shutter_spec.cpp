#include "api/shutter_spec.h"

#include "camera/exposure.h"

namespace lensrt {

double ShutterSpec::shutterSeconds() const {
  return seconds.value_or(Exposure{}.shutterSeconds);
}

ShutterTiming ShutterSpec::timing() const {
  ShutterTiming t;
  t.shutterSeconds = shutterSeconds();
  t.readoutSeconds = readoutSeconds;
  t.readout = readout;
  t.rampFraction = rampFraction;
  return t;
}

}  // namespace lensrt
