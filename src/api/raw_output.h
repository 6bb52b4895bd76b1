// --raw OUT.dng and --cfa: the render as the raw file a camera would write,
// a colour filter mosaic in a DNG (sensor/dng_file.h) that raw developers
// (dcraw, LibRaw, Lightroom, darktable) develop.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "api/sensor_readout.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "color/color_space.h"
#include "image/image.h"
#include "sensor/mosaic.h"

namespace lensrt {

struct RawOutputOptions {
  std::string file;  // empty: no raw file
  CfaPattern cfa;    // RGGB unless --cfa says otherwise
};

// A .dng name (UsageError naming --raw); the
// folder is created and must take a new file (InputError), before any work.
void checkRawOutput(const RawOutputOptions& options);

// Writes the raw file of `image` (its R, G, B: after a sensor readout, the
// DN of each site's colour that its reading came from).
// With a camera response's RGB (`cameraRgb`, FilmColour::camera) the mosaic
// holds camera RGB, unbalanced, with the response's ColorMatrix1 and the
// white balance as AsShotNeutral, as a camera's raw file. Otherwise the
// camera is the image's RGB: ColorMatrix1 is XYZ to the output space (linear
// sRGB by default) under D65, AsShotNeutral 1, 1, 1. `exposure` gives the
// file's exposure time and ISO.
void writeRawOutput(const RawOutputOptions& options, const Image& image,
                    const std::optional<SensorReadout>& readout, const Camera& camera,
                    const std::optional<ColorSpaceId>& outputSpace, const Exposure& exposure,
                    const std::optional<CameraRgb>& cameraRgb);

}  // namespace lensrt
