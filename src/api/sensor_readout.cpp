#include "api/sensor_readout.h"

#include <fmt/core.h>

#include <cmath>
#include <vector>

#include "core/error.h"

namespace lensrt {

std::string SensorReadout::describe() const {
  const SensorParams& p = params;
  return fmt::format(
             "{}: full well {:g} e, {:g} DN/e x {:g}, read noise {:g} e, dark {:g} e/s, PRNU {:g}%, DSNU "
             "{:g}%, "
             "{}-bit ADC, black {:g} DN, QE {:g}",
             p.name, p.fullWellE, p.gainDnPerE, exposure.analogGain, p.readNoiseE, p.darkCurrentEPerS,
             p.prnuPercent, p.dsnuPercent, p.adcBits, p.blackLevelDn, p.quantumEfficiency) +
         (camera ? ", read in the camera's RGB" : "");
}

std::optional<SensorReadout> sensorReadout(const SensorSpec& o, const Exposure& exposure,
                                           const FilmGeometry& film,
                                           const std::optional<CameraRgb>& cameraRgb) {
  if (!o.noise) return std::nullopt;
  SensorReadout r;
  r.camera = cameraRgb;
  r.params = sensorParams(o.params.empty() ? "default" : o.params);
  const double shutter = exposure.shutterSeconds;
  r.physical = exposure.mode == ExposureMode::Physical;
  const double pitchX = film.sensorWidthMm / film.width * 1e-3,
               pitchY = film.sensorHeightMm / film.height * 1e-3;
  r.pixelPitchUm = std::sqrt(pitchX * pitchY) * 1e6;
  if (r.physical) {
    r.exposure = physicalSensorExposure(r.params, exposure.iso, shutter, pitchX * pitchY);
  } else {
    r.exposure = normalizedSensorExposure(r.params, shutter);
  }
  return r;
}

void addSensorIdentity(ImageMetadata& identity, const std::optional<SensorReadout>& readout) {
  if (readout) identity["lensrt:settings"] += " sensor_noise=" + readout->params.name;
}

Vec3d sensorChannelGains(const SensorReadout& r) {
  return r.camera && r.physical ? r.camera->relativeElectrons : Vec3d{1, 1, 1};
}

Mat3d imageToSensorValues(const SensorReadout& r) {
  if (!r.camera) return Mat3d{};
  return Mat3d::diagonal(sensorChannelGains(r)) * r.camera->fromImage;
}

namespace {
// One line: how much clips, at what pitch, and what to change.
void warnOfClipping(const SensorReadout& r, double share, Warnings& warnings) {
  if (!(share > kClippedShareToWarn)) return;
  const std::string what = fmt::format("{:.0f}% of the pixels clip at the sensor's full well ({:g} e)",
                                       100 * share, r.params.fullWellE);
  warnings.warn(
      r.physical
          ? fmt::format(
                "{}: its {:.3g} um pixels collect {:.3g} electrons at an image value of 1; use smaller "
                "pixels (a smaller --sensor, or more of them with --res) or a lower exposure (--iso, "
                "--shutter, --fstop)",
                what, r.pixelPitchUm, r.exposure.electronsPerValue)
          : fmt::format(
                "{}: --exposure normalized fills the well at an image value of 1, whatever the pixel "
                "pitch ({:.3g} um), and the image is brighter; use a lower exposure (dimmer lights, or "
                "--exposure physical with --iso and --shutter)",
                what, r.pixelPitchUm));
}
}  // namespace

void readOut(const SensorReadout& r, Image& image, ImageMetadata& metadata, std::uint64_t seed,
             Warnings& warnings) {
  if (!r.camera) {
    applySensorReadout(image, r.params, r.exposure, seed);
    warnOfClipping(r, clippedShare(image, r.params, r.exposure), warnings);
  } else {
    // Read in the camera's channels, then back to the image's RGB; the
    // noiseless channels keep the render's own values, not a round trip.
    const Mat3d toSensor = imageToSensorValues(r);
    const int red = image.channelIndex("R");
    std::vector<float> render;
    render.reserve(std::size_t(image.width) * std::size_t(image.height) * 3);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c) render.push_back(image.at(x, y, red + c));
    transformRgb(image, toSensor);
    applySensorReadout(image, r.params, r.exposure, seed);
    warnOfClipping(r, clippedShare(image, r.params, r.exposure), warnings);
    transformRgb(image, *toSensor.inverse());
    const int noiseless = image.channelIndex("noiseless.R");
    std::size_t i = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        for (int c = 0; c < 3; ++c) image.at(x, y, noiseless + c) = render[i++];
    const Vec3d e = sensorChannelGains(r) * r.exposure.electronsPerValue;
    metadata["lensrt:sensor_channel_electrons"] = fmt::format("{:.9g} {:.9g} {:.9g}", e.x, e.y, e.z);
  }
  metadata["lensrt:sensor_noise"] = r.describe();
  metadata["lensrt:sensor_electrons_per_value"] = fmt::format("{:.9g}", r.exposure.electronsPerValue);
  metadata["lensrt:sensor_dn_per_electron"] =
      fmt::format("{:.9g}", r.params.gainDnPerE * r.exposure.analogGain);
}

}  // namespace lensrt
