// --noise on and --sensor-params: the sensor's readout (sensor/readout.h)
// of a render, with the exposure the camera options give it.
#pragma once

#include <optional>
#include <string>

#include "api/sensor_spec.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "core/warnings.h"
#include "image/image.h"
#include "sensor/camera_rgb.h"
#include "sensor/readout.h"
#include "sensor/sensor_params.h"

namespace lensrt {

struct SensorReadout {
  SensorParams params;
  SensorExposure exposure;
  bool physical = false;    // --exposure physical: the curves count as quantum efficiency
  double pixelPitchUm = 0;  // the film's, for the clipping warning
  // A camera response's own RGB (FilmColour::camera): then the sensor counts
  // electrons in the camera's channels, not in the image's RGB.
  std::optional<CameraRgb> camera;
  // lensrt:sensor_noise: "default: full well 20000 e, 0.2 DN/e x 1, read 3 e, ..."
  std::string describe() const;
};

// None with --noise off. Physical exposure gives electrons from the lux
// seconds on a pixel of the film's pitch; normalized exposure fills the well
// at an image value of 1.0. Throws UsageError / InputError for bad settings.
std::optional<SensorReadout> sensorReadout(const SensorSpec& sensor, const Exposure& exposure,
                                           const FilmGeometry& film,
                                           const std::optional<CameraRgb>& cameraRgb);

// Appends " sensor_noise=NAME" to lensrt:settings (an identity key: a noisy
// and a noiseless part never merge); nothing without a readout.
void addSensorIdentity(ImageMetadata& identity, const std::optional<SensorReadout>& readout);

// The readout applied to a render's image, with its metadata
// (lensrt:sensor_noise, lensrt:sensor_electrons_per_value,
// lensrt:sensor_dn_per_electron, and with a camera's RGB
// lensrt:sensor_channel_electrons; the identity's part is addSensorIdentity's). With a camera's
// RGB, each channel is read in camera RGB and the reading turned back into
// the image's RGB; noiseless.R/G/B keep the render. When more than
// kClippedShareToWarn of the pixels clip, one warning gives the share, the
// pixel pitch and the way out.
void readOut(const SensorReadout& readout, Image& image, ImageMetadata& metadata, std::uint64_t seed,
             Warnings& warnings);

// Each camera channel's electrons relative to the readout's basis:
// CameraRgb::relativeElectrons with physical exposure, else 1.
Vec3d sensorChannelGains(const SensorReadout& readout);

// A camera's RGB as the sensor reads it: camera RGB times sensorChannelGains,
// so that the readout's electrons per value apply to every channel; the
// identity without a camera's RGB.
Mat3d imageToSensorValues(const SensorReadout& readout);

}  // namespace lensrt
