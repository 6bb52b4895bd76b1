#include "api/film_colour.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>

#include "color/chromatic_adaptation.h"
#include "color/cie.h"
#include "color/color_space.h"
#include "color/illuminant.h"
#include "color/rgb_to_spectrum.h"
#include "core/error.h"

namespace lensrt {

namespace {

constexpr double kMinKelvin = 1500, kMaxKelvin = 25000;

// --white-balance as a colour temperature, or none for "none" and "auto".
std::optional<double> parseKelvin(const std::string& text) {
  if (text == "none" || text == "auto") return std::nullopt;
  std::string number = text;
  if (!number.empty() && (number.back() == 'K' || number.back() == 'k')) number.pop_back();
  char* end = nullptr;
  const double k = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !(k >= kMinKelvin && k <= kMaxKelvin))
    throw UsageError(
        "--white-balance",
        fmt::format("expected auto, none or a colour temperature from {:g} to {:g} K (e.g. 5500), "
                    "got '{}'",
                    kMinKelvin, kMaxKelvin, text));
  return k;
}

std::string responseName(const CameraOptions& o) {
  return o.sensorResponse.empty() ? "cie1931" : o.sensorResponse;
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

}  // namespace

void checkColourOptions(const CameraOptions& o) {
  if (o.spectral == "off") {
    if (!o.sensorResponse.empty())
      throw UsageError("--sensor-response", "needs spectral transport (--spectral on)");
    if (!o.whiteBalance.empty())
      throw UsageError("--white-balance", "needs spectral transport (--spectral on)");
    if (o.outputSpace != "srgb")
      throw UsageError("--output-space", "needs spectral transport (--spectral on)");
    return;
  }
  if (!o.whiteBalance.empty()) parseKelvin(o.whiteBalance);
  if (o.outputSpace == "camera")
    throw UsageError("--output-space",
                     "camera is the RGB of a camera's response; the CIE 1931 observer has none "
                     "(choose --sensor-response, or srgb, rec2020, acescg, xyz)");
  if (!parseColorSpace(o.outputSpace))
    throw UsageError("--output-space",
                     "expected srgb, rec2020, acescg, xyz or camera, got '" + o.outputSpace + "'");
  if (responseName(o) != "cie1931")
    throw UsageError("--sensor-response", "unknown response '" + o.sensorResponse + "' (known: cie1931)");
}

std::shared_ptr<const FilmResponse> filmResponse(const CameraOptions& o, const std::optional<Rgb>& sceneLight,
                                                 Warnings& warnings) {
  checkColourOptions(o);
  if (o.spectral == "off") return nullptr;
  const std::string wb = o.whiteBalance.empty() ? "none" : o.whiteBalance;
  const ColorSpace& space = colorSpace(*parseColorSpace(o.outputSpace));
  if (wb == "none" && space.id == ColorSpaceId::Srgb)
    // The built-in response lives as long as the program: a non-owning pointer.
    return std::shared_ptr<const FilmResponse>(std::shared_ptr<const void>(), &FilmResponse::cie1931Srgb());

  // The white balance's illuminant, and what it is called in the metadata.
  FilmResponse::Info info;
  info.outputSpace = std::string(space.name);
  info.chromaticities =
      fmt::format("{:g} {:g} {:g} {:g} {:g} {:g} {:.6g} {:.6g}", space.red.x, space.red.y, space.green.x,
                  space.green.y, space.blue.x, space.blue.y, space.white.x, space.white.y);
  std::function<double(double)> neutral = atUnitY([](double nm) { return d65(nm); });
  if (const std::optional<double> kelvin = parseKelvin(wb)) {
    neutral = atUnitY([k = *kelvin](double nm) { return whiteSpectrum(k, nm); });
    info.whiteBalance = fmt::format("{:g}K", *kelvin);
  } else if (wb == "auto") {
    if (sceneLight && maxComponent(*sceneLight) > 0) {
      neutral = atUnitY(lightOfColour(*sceneLight));
      const Vec2d xy = chromaticity(spectrumToXyz(neutral));
      info.whiteBalance = fmt::format("auto:x={:.4f},y={:.4f}", xy.x, xy.y);
    } else {
      warnings.warn("--white-balance auto: the scene has no light to balance to; keeping D65");
      info.whiteBalance = "auto:none";
    }
  }
  // XYZ adapted from the neutral's white to the output's (CIE XYZ: to D65,
  // or left alone without a white balance).
  const Vec3d source = spectrumToXyz(neutral);
  const Vec3d d65White = spectrumToXyz(atUnitY([](double nm) { return d65(nm); }));
  Vec3d target = space.rgbToXyz * Vec3d{1, 1, 1};
  if (space.id == ColorSpaceId::Xyz) target = d65White;
  const Mat3d adapt =
      (space.id == ColorSpaceId::Xyz && wb == "none") ? Mat3d{} : bradfordAdaptation(source, target);
  return std::make_shared<const FilmResponse>(FilmResponse::make(
      info, [](double nm) { return cieXyzMatching(nm) / kCieYIntegral; }, space.xyzToRgb * adapt, neutral,
      space.xyzToRgb * target, FilmResponse::cie1931SamplingWeight));
}

std::string transportDescription(const FilmResponse* response) {
  if (!response) return "rgb";
  std::string s = "spectral:";
  s += response->describe();
  return s;
}

}  // namespace lensrt
