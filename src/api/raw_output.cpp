#include "api/raw_output.h"

#include <cmath>
#include <filesystem>

#include "api/output_file.h"
#include "color/chromatic_adaptation.h"
#include "color/color_space.h"
#include "core/error.h"
#include "image/capture_date.h"
#include "sensor/dng_file.h"
#include "sensor/mosaic.h"

namespace lensrt {

namespace {

// DNG's ColorMatrix1: XYZ under its calibration illuminant (D65) to the raw's
// RGB. The mosaic holds the image's RGB, which is the output space's, white
// balanced so that D65 (or the chosen white) records that space's white: the
// space's XYZ-to-RGB after the adaptation from D65 to its white.
std::array<double, 9> rowMajor(const Mat3d& m) {
  std::array<double, 9> out{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[std::size_t(3 * r + c)] = m(r, c);
  return out;
}

std::array<double, 9> rawColorMatrix(const std::optional<ColorSpaceId>& id) {
  if (!id || *id == ColorSpaceId::Srgb) return kXyzToLinearSrgb;
  const ColorSpace& space = colorSpace(*id);
  const Vec3d d65 = colorSpace(ColorSpaceId::Srgb).rgbToXyz * Vec3d{1, 1, 1};
  return rowMajor(*id == ColorSpaceId::Xyz
                      ? Mat3d{}
                      : space.xyzToRgb * bradfordAdaptation(d65, space.rgbToXyz * Vec3d{1, 1, 1}));
}

// The image's R, G, B in the camera's channels, as the sensor read them
// (imageToSensorValues) or, without a readout, as camera RGB.
Image cameraChannels(const Image& image, const std::optional<SensorReadout>& readout,
                     const CameraRgb& cameraRgb) {
  Image out(image.width, image.height, {"R", "G", "B"});
  out.originX = image.originX, out.originY = image.originY;
  out.frameWidth = image.frameWidth, out.frameHeight = image.frameHeight;
  const int red = image.channelIndex("R");
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = image.at(x, y, red + c);
  transformRgb(out, readout ? imageToSensorValues(*readout) : cameraRgb.fromImage);
  return out;
}

}  // namespace

void checkRawOutput(const RawOutputOptions& o) {
  if (o.file.empty()) return;
  if (std::filesystem::path(o.file).extension() != ".dng")
    throw UsageError("--raw", "expected a .dng file, got '" + o.file + "'");
  createFolderFor(o.file);
}

void writeRawOutput(const RawOutputOptions& o, const Image& image,
                    const std::optional<SensorReadout>& readout, const Camera& camera,
                    const std::optional<ColorSpaceId>& outputSpace, const Exposure& exposure,
                    const std::optional<CameraRgb>& cameraRgb) {
  const CfaPattern& pattern = o.cfa;
  std::optional<Image> inCamera;
  if (cameraRgb) inCamera = cameraChannels(image, readout, *cameraRgb);
  const Image& sites = inCamera ? *inCamera : image;
  const Mosaic mosaic = readout ? makeMosaic(sites, pattern, &readout->params, &readout->exposure)
                                : makeMosaic(sites, pattern, nullptr, nullptr);
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
  // Make and Model name the camera whose response the film has; lensrt's
  // model and lens otherwise (LensModel names the lens either way).
  if (cameraRgb && !cameraRgb->model.empty()) {
    d.make = cameraRgb->maker;
    d.model = cameraRgb->model;
  } else {
    d.model = info.model + (info.lens.empty() ? "" : " " + info.lens);
  }
  d.lensModel = info.lens;
  const FilmGeometry& film = camera.film();
  const double kFullFrameDiagonalMm = std::hypot(36.0, 24.0);  // the 35 mm film frame
  const double diagonal = std::hypot(film.sensorWidthMm, film.sensorHeightMm);
  if (info.focalLengthMm > 0 && diagonal > 0)
    d.focalLengthIn35mmFilm = int(std::lround(info.focalLengthMm * kFullFrameDiagonalMm / diagonal));
  if (film.sensorWidthMm > 0) d.focalPlanePixelsPerCm = film.width / (film.sensorWidthMm / 10.0);
  d.dateTimeOriginal = captureDate();
  // The file describes the mosaic it holds: a readout's photon counts scale
  // the camera's channels (cameraChannels), and its matrix and neutral with them.
  if (cameraRgb)
    describeCameraColour(d, *cameraRgb, readout ? sensorChannelGains(*readout) : Vec3d{1, 1, 1});
  else
    d.colorMatrix1 = rawColorMatrix(outputSpace);
  d.exposureSeconds = exposure.shutterSeconds;
  d.iso =
      exposure.mode == ExposureMode::Physical ? exposure.iso : (readout ? readout->params.baseIso : 100.0);
  d.fNumber = info.fNumber;
  d.focalLengthMm = info.focalLengthMm;
  writeDng(o.file, mosaic, d);
}

}  // namespace lensrt
