// --raw OUT.dng and --cfa: the render as the raw file a camera would write,
// a colour filter mosaic in a DNG (sensor/dng_file.h) that raw developers
// (dcraw, LibRaw, Lightroom, darktable) develop.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "api/camera_options.h"
#include "api/sensor_readout.h"
#include "camera/camera.h"
#include "image/image.h"

namespace lensrt {

struct RawOutputOptions {
  std::string file;          // empty: no raw file
  std::string cfa = "RGGB";  // RGGB, BGGR, GRBG or GBRG
};

// A .dng name and a known pattern (UsageError naming --raw or --cfa); the
// folder is created and must take a new file (InputError), before any work.
void checkRawOutput(const RawOutputOptions& options);

// Writes the raw file of `image` (its R, G, B: after a sensor readout, the
// DN of each site's colour that its reading came from).
// The camera is a linear Rec.709 (sRGB primaries) one: ColorMatrix1 is XYZ
// to linear sRGB under D65, AsShotNeutral 1, 1, 1.
void writeRawOutput(const RawOutputOptions& options, const Image& image,
                    const std::optional<SensorReadout>& readout, const Camera& camera,
                    const CameraOptions& cameraOptions);

}  // namespace lensrt
