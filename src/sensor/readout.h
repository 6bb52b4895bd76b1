// The sensor's readout of a rendered exposure: photo-electrons from the image
// value, then in this order Poisson shot noise, dark current (itself Poisson),
// read noise, the fixed patterns PRNU (a per-pixel gain) and DSNU (a
// per-pixel dark-current spread), clipping at full well, the analog gain of
// the ISO and quantisation by the ADC with its black level.
//
// Random numbers come from a counter-based generator keyed by the pixel's
// place in the whole frame and its channel: temporal noise by the render's
// seed, fixed patterns by the sensor's own seed. A tile, an MPI rank's strip
// or a resumed render reads out the same numbers as the whole frame in one go.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "sensor/sensor_params.h"

namespace lensrt {

// Photons per lux second per square metre of light at 555 nm, where
// 683 lm/W holds: 1 / (683 * h c / 555 nm).
inline constexpr double kPhotonsPerLuxSecondM2 = 4.0903e15;

struct SensorExposure {
  double electronsPerValue = 0.0;  // mean photo-electrons of an image value of 1.0
  double exposureSeconds = 0.01;   // for the dark current
  double analogGain = 1.0;         // ISO / base ISO
};

// `--exposure physical`: a value of 1.0 is the ISO 12232 saturation exposure
// 78 / ISO lux seconds (camera/exposure.h), which puts
// 78 / ISO * kPhotonsPerLuxSecondM2 * pixel area * QE electrons in a pixel.
SensorExposure physicalSensorExposure(const SensorParams& params, double iso, double shutterSeconds,
                                      double pixelAreaM2);
// `--exposure normalized`: a value of 1.0 fills the well (the raw file's
// white level), at the base ISO.
SensorExposure normalizedSensorExposure(const SensorParams& params, double shutterSeconds);

// The ADC's reading (DN) of one pixel's channel whose noiseless value is
// `value`; (frameX, frameY) place it in the whole frame.
double readoutDn(const SensorParams& params, const SensorExposure& exposure, double value, int frameX,
                 int frameY, int channel, std::uint64_t seed);

// The DN of `dn` in image-value units: (DN - black) / (DN per electron) /
// electrons per value, so that a noiseless reading returns about the value.
double dnToValue(const SensorParams& params, const SensorExposure& exposure, double dn);

// Replaces R, G, B of `image` (image values) by the sensor's reading in the
// same units and adds the noiseless values as noiseless.R/G/B.
void applySensorReadout(Image& image, const SensorParams& params, const SensorExposure& exposure,
                        std::uint64_t seed);

// The share of `image`'s pixels whose reading (R, G, B after
// applySensorReadout) is at the sensor's saturation in some channel: a full
// well, or the ADC's top where that comes first. Readings are exact DN
// values, so the test is exact.
double clippedShare(const Image& image, const SensorParams& params, const SensorExposure& exposure);

// Above this share of clipped pixels the readout says so: a photo's lamps
// and sun glints clip a few per cent of it; more is an exposure (or a pixel
// size) the sensor cannot hold.
inline constexpr double kClippedShareToWarn = 0.05;

}  // namespace lensrt
