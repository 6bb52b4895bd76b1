#include "api/raw_output.h"

#include <filesystem>

#include "api/output_file.h"
#include "core/error.h"
#include "sensor/dng_file.h"
#include "sensor/mosaic.h"

namespace lensrt {

void checkRawOutput(const RawOutputOptions& o) {
  if (!parseCfaPattern(o.cfa))
    throw UsageError("--cfa", "expected RGGB, BGGR, GRBG or GBRG, got '" + o.cfa + "'");
  if (o.file.empty()) return;
  if (std::filesystem::path(o.file).extension() != ".dng")
    throw UsageError("--raw", "expected a .dng file, got '" + o.file + "'");
  createFolderFor(o.file);
}

void writeRawOutput(const RawOutputOptions& o, const Image& image,
                    const std::optional<SensorReadout>& readout, const Camera& camera,
                    const CameraOptions& options) {
  const CfaPattern pattern = *parseCfaPattern(o.cfa);
  const Mosaic mosaic = readout ? makeMosaic(image, pattern, &readout->params, &readout->exposure)
                                : makeMosaic(image, pattern, nullptr, nullptr);
  const CameraInfo info = camera.info();
  DngDescription d;
  // The pattern is placed by the frame (a tile's mosaic is the frame's): the
  // file declares it as seen from its own first pixel.
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      const int colour = pattern.colourAt(image.originX + x, image.originY + y);
      d.pattern.colours[std::size_t(y * 2 + x)] = colour;
      d.pattern.name[std::size_t(y * 2 + x)] = "RGB"[colour];
    }
  d.model = info.model + (info.lens.empty() ? "" : " " + info.lens);
  d.colorMatrix1 = kXyzToLinearSrgb;
  d.exposureSeconds = shutterSeconds(options);
  d.iso = options.exposure == "physical" ? options.iso.value_or(100.0)
                                         : (readout ? readout->params.baseIso : 100.0);
  d.fNumber = info.fNumber;
  d.focalLengthMm = info.focalLengthMm;
  writeDng(o.file, mosaic, d);
}

}  // namespace lensrt
