#include "api/sensor_readout.h"

#include <fmt/core.h>

#include "core/error.h"

namespace lensrt {

std::string SensorReadout::describe() const {
  const SensorParams& p = params;
  return fmt::format(
      "{}: full well {:g} e, {:g} DN/e x {:g}, read noise {:g} e, dark {:g} e/s, PRNU {:g}%, DSNU {:g}%, "
      "{}-bit ADC, black {:g} DN, QE {:g}",
      p.name, p.fullWellE, p.gainDnPerE, exposure.analogGain, p.readNoiseE, p.darkCurrentEPerS, p.prnuPercent,
      p.dsnuPercent, p.adcBits, p.blackLevelDn, p.quantumEfficiency);
}

std::optional<SensorReadout> sensorReadout(const CameraOptions& o, const FilmGeometry& film) {
  // checkCameraOptions (run by makeCamera, before this) refused --sensor-params without --noise on.
  if (o.noise == "off") return std::nullopt;
  SensorReadout r;
  r.params = sensorParams(o.sensorParams.empty() ? "default" : o.sensorParams);
  const double shutter = shutterSeconds(o);
  if (o.exposure == "physical") {
    const double pitchX = film.sensorWidthMm / film.width * 1e-3,
                 pitchY = film.sensorHeightMm / film.height * 1e-3;
    r.exposure = physicalSensorExposure(r.params, o.iso.value_or(100.0), shutter, pitchX * pitchY);
  } else {
    r.exposure = normalizedSensorExposure(r.params, shutter);
  }
  return r;
}

void addSensorIdentity(ImageMetadata& identity, const std::optional<SensorReadout>& readout) {
  if (readout) identity["lensrt:settings"] += " sensor_noise=" + readout->params.name;
}

void readOut(const SensorReadout& r, Image& image, ImageMetadata& metadata, std::uint64_t seed) {
  applySensorReadout(image, r.params, r.exposure, seed);
  addSensorIdentity(metadata, r);
  metadata["lensrt:sensor_noise"] = r.describe();
  metadata["lensrt:sensor_electrons_per_value"] = fmt::format("{:.9g}", r.exposure.electronsPerValue);
  metadata["lensrt:sensor_dn_per_electron"] =
      fmt::format("{:.9g}", r.params.gainDnPerE * r.exposure.analogGain);
}

}  // namespace lensrt
