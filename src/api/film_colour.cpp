#include "api/film_colour.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "color/chromatic_adaptation.h"
#include "color/cie.h"
#include "color/color_space.h"
#include "color/illuminant.h"
#include "color/rgb_to_spectrum.h"
#include "core/error.h"
#include "sensor/color_checker.h"

namespace lensrt {

namespace {

std::string responseName(const ColourSpec& o) {
  return o.sensorResponse.empty() ? std::string(kCie1931Response) : o.sensorResponse;
}

// A spectrum over 360-830 nm scaled to luminance Y = 1.
std::function<double(double)> atUnitY(std::function<double(double)> spectrum) {
  const double y = spectrumToXyz(spectrum).y;
  return [spectrum = std::move(spectrum), y](double nm) { return spectrum(nm) / y; };
}

// The light of an RGB colour: its smooth spectrum (scaled into the table as
// pbrt-v4's illuminant spectra are) times D65.
std::function<double(double)> lightOfColour(const Rgb& c) {
  const float m = maxComponent(c);
  const SigmoidPolynomial s = RgbToSpectrumTable::srgb()(c / (2 * m));
  return [s](double nm) { return double(s(float(nm))) * d65(nm); };
}

void checkCameraSpace(const ColourSpec& o, const SensorResponse& sensor) {
  if (!o.outputSpace && sensor.cie1931)
    throw UsageError("--output-space",
                     "camera is the RGB of a camera's response; the CIE 1931 observer has none "
                     "(choose --sensor-response, or srgb, rec2020, acescg, xyz)");
}

// The camera's own RGB beside the film's (sensor/camera_rgb.h). `green`:
// what its green records of D65 at Y = 1, camera RGB's unit; `neutral`: what
// it records of the white balance's illuminant.
CameraRgb cameraRgb(const SensorResponse& sensor, const FilmResponse& film, double green,
                    const Vec3d& neutral, const std::function<double(double)>& d65AtUnitY) {
  CameraRgb c;
  c.maker = sensor.maker;
  c.model = sensor.model;
  c.toImage = film.sensorToOutput() * Mat3d::diagonal({green, green, green});
  c.fromImage = *c.toImage.inverse();  // make() refused a film that records no white
  c.asShotNeutral = neutral / neutral.y;
  // The curves as quantum efficiency (their peak is the sensor's QE): a
  // camera value of 1 is `green` of the curves' integral over the light,
  // whose photons are counted at the channel's mean wavelength under D65,
  // against the basis's 555 nm.
  double peak = 0;
  Vec3d weight{0, 0, 0}, weightedNm{0, 0, 0};
  for (double nm = FilmResponse::kMinNm; nm <= FilmResponse::kMaxNm; nm += 1) {
    const Vec3d s = sensor.at(nm);
    peak = std::max({peak, s.x, s.y, s.z});
    weight += s * d65AtUnitY(nm);
    weightedNm += s * (d65AtUnitY(nm) * nm);
  }
  // (`green` is in the units of spectrumToXyz, whose Y is the ybar integral
  // over kCieYIntegral: luminance 1 is kCieYIntegral of ybar.)
  c.relativeElectrons = (weightedNm / weight) * (green / peak / kCieYIntegral / 555.0);
  // DNG's ColorMatrix1: XYZ to camera RGB under D65, the inverse of the
  // chart's fit under D65 (in camera RGB's unit).
  const Mat3d cameraToXyz = fitCameraToXyz(sensor, d65AtUnitY) * Mat3d::diagonal({green, green, green});
  const std::optional<Mat3d> xyzToCamera = cameraToXyz.inverse();
  if (!xyzToCamera)
    throw InputError(sensor.name, "the response's channels are not independent: no colour matrix fits");
  c.xyzToCamera = *xyzToCamera;
  return c;
}

}  // namespace

void checkColourSpec(const ColourSpec& o) {
  if (o.transport == Transport::Rgb) return;
  // An unknown name or a bad file fails before the scene loads.
  checkCameraSpace(o, loadSensorResponse(responseName(o)));
}

FilmColour filmColour(const ColourSpec& o, const std::optional<Rgb>& sceneLight, Warnings& warnings) {
  // Auto is resolved by the plan (api/transport_choice.h) before the film is built.
  if (o.transport != Transport::Spectral) return {};
  const SensorResponse sensor = loadSensorResponse(responseName(o));  // read once here
  checkCameraSpace(o, sensor);
  // Cameras balance automatically by default, as a camera does; the CIE
  // observer records colorimetry (D65 is white).
  using Kind = WhiteBalance::Kind;
  const WhiteBalance wb =
      o.whiteBalance ? *o.whiteBalance : WhiteBalance{sensor.cie1931 ? Kind::None : Kind::Auto};
  const bool cameraSpace = !o.outputSpace;
  const ColorSpace& space = colorSpace(o.outputSpace.value_or(ColorSpaceId::Srgb));
  if (sensor.cie1931 && wb.kind == Kind::None && space.id == ColorSpaceId::Srgb)
    // The built-in response lives as long as the program: a non-owning pointer.
    return {std::shared_ptr<const FilmResponse>(std::shared_ptr<const void>(), &FilmResponse::cie1931Srgb()),
            std::nullopt};

  FilmResponse::Info info;
  info.response = sensor.name;
  info.outputSpace = cameraSpace ? "camera" : std::string(space.name);
  if (!cameraSpace)
    info.chromaticities =
        fmt::format("{:g} {:g} {:g} {:g} {:g} {:g} {:.6g} {:.6g}", space.red.x, space.red.y, space.green.x,
                    space.green.y, space.blue.x, space.blue.y, space.white.x, space.white.y);
  // The white balance's illuminant (Y = 1), and what the metadata calls it.
  const auto d65AtUnitY = atUnitY([](double nm) { return d65(nm); });
  std::function<double(double)> neutral = d65AtUnitY;
  info.whiteBalance = "none";
  if (wb.kind == Kind::Kelvin) {
    neutral = atUnitY([k = wb.kelvin](double nm) { return whiteSpectrum(k, nm); });
    info.whiteBalance = fmt::format("{:g}K", wb.kelvin);
  } else if (wb.kind == Kind::Auto) {
    if (sceneLight && maxComponent(*sceneLight) > 0) {
      neutral = atUnitY(lightOfColour(*sceneLight));
      const Vec2d xy = chromaticity(spectrumToXyz(neutral));
      info.whiteBalance = fmt::format("auto:x={:.4f},y={:.4f}", xy.x, xy.y);
    } else {
      warnings.warn("--white-balance auto: the scene has no light to balance to; keeping D65");
      info.whiteBalance = "auto:none";
    }
  }

  // The output's white in XYZ (CIE XYZ has none: D65's), which the neutral
  // is adapted to and records exactly.
  const Vec3d target =
      space.id == ColorSpaceId::Xyz ? spectrumToXyz(d65AtUnitY) : space.rgbToXyz * Vec3d{1, 1, 1};
  if (sensor.cie1931) {
    // XYZ adapted from the neutral's white to the output's (CIE XYZ without a
    // white balance is left alone).
    const Mat3d adapt = (space.id == ColorSpaceId::Xyz && wb.kind == Kind::None)
                            ? Mat3d{}
                            : bradfordAdaptation(spectrumToXyz(neutral), target);
    return {std::make_shared<const FilmResponse>(FilmResponse::make(
                info, [](double nm) { return cieXyzMatching(nm) / kCieYIntegral; }, space.xyzToRgb * adapt,
                neutral, space.xyzToRgb * target, FilmResponse::cie1931SamplingWeight)),
            std::nullopt};
  }

  // A camera: its R, G, B curves, drawn in proportion to their sum under D65.
  const auto curves = [&sensor](double nm) { return sensor.at(nm); };
  const auto samplingWeight = [&sensor](double nm) {
    const Vec3d c = sensor.at(nm);
    return (c.x + c.y + c.z) * d65(nm);
  };
  const Vec3d d65Recorded = FilmResponse::recorded(curves, d65AtUnitY);
  std::shared_ptr<const FilmResponse> film;
  if (cameraSpace) {
    // The camera's own RGB, unbalanced as a raw file is (the white balance
    // is the metadata's): scaled as one so that D65's green records 1.
    film = std::make_shared<const FilmResponse>(
        FilmResponse::make(info, curves, Mat3d{}, d65AtUnitY, d65Recorded / d65Recorded.y, samplingWeight));
  } else {
    // Camera RGB to XYZ: the least-squares 3x3 over the ColorChecker's 24
    // patches lit by the white balance's illuminant (pbrt-v4's PixelSensor),
    // then adapted to the output's white; the grey card is then exact.
    const Mat3d toXyz = fitCameraToXyz(sensor, neutral);
    const Mat3d adapt = bradfordAdaptation(spectrumToXyz(neutral), target);
    film = std::make_shared<const FilmResponse>(FilmResponse::make(
        info, curves, space.xyzToRgb * adapt * toXyz, neutral, space.xyzToRgb * target, samplingWeight));
  }
  return {film, cameraRgb(sensor, *film, d65Recorded.y, FilmResponse::recorded(curves, neutral), d65AtUnitY)};
}

Mat3d fitCameraToXyz(const SensorResponse& sensor, const std::function<double(double)>& illuminant) {
  // Normal equations of min sum |M c_p - x_p|^2: M = (sum x c^T)(sum c c^T)^-1.
  Mat3d xc, cc;
  xc.m = {};
  cc.m = {};
  for (const ColorCheckerPatch& patch : colorCheckerPatches()) {
    Vec3d c{0, 0, 0}, x{0, 0, 0};
    for (double nm = kCieMinNm; nm <= kCieMaxNm; nm += 1) {
      const double light = patch.at(nm) * illuminant(nm);
      c += sensor.at(nm) * light;
      x += cieXyzMatching(nm) * (light / kCieYIntegral);
    }
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) {
        xc.m[i][j] += x[i] * c[j];
        cc.m[i][j] += c[i] * c[j];
      }
  }
  const std::optional<Mat3d> inverse = cc.inverse();
  if (!inverse)
    throw InputError(sensor.name, "the response's channels are not independent: no colour matrix fits");
  return xc * *inverse;
}

std::string transportDescription(const FilmResponse* response) {
  if (!response) return "rgb";
  std::string s = "spectral:";
  s += response->describe();
  return s;
}

}  // namespace lensrt
