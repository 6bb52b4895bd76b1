#include "api/camera_options.h"

#include <fmt/core.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

#include "api/aperture_mask_file.h"
#include "api/film_colour.h"
#include "api/keyframes.h"
#include "api/lens_loading.h"
#include "camera/lens_camera.h"
#include "camera/orthographic_camera.h"
#include "camera/pinhole_camera.h"
#include "camera/thick_lens_camera.h"
#include "camera/thin_lens_camera.h"
#include "core/constants.h"
#include "core/error.h"
#include "optics/chromatic.h"
#include "optics/focus.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

std::optional<double> parseDouble(std::string_view s) {
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

const std::map<std::string, Vec2d>& sensorNames() {
  static const std::map<std::string, Vec2d> names{
      {"full-frame", {36.0, 24.0}}, {"aps-c", {23.6, 15.6}}, {"mft", {17.3, 13.0}}, {"1in", {13.2, 8.8}}};
  return names;
}

std::string metresText(double m) {
  return std::isinf(m) ? "inf" : fmt::format("{:.4g}", m);
}

}  // namespace

// "auto" -> nullopt; "inf"/"infinity" -> infinity; keyframes at the time;
// else positive metres.
std::optional<double> parseFocus(const std::string& text, double seconds) {
  if (isKeyframes(text))
    return valueAt(parseKeyframes(
                       "--focus", text, [](double m) { return m > 0.0; }, "METRES"),
                   seconds);
  if (text == "auto") return std::nullopt;
  if (text == "inf" || text == "infinity") return kInfinity;
  const auto v = parseDouble(text);
  if (!v || !(*v > 0.0))
    throw UsageError(
        "--focus",
        "expected a distance in metres > 0, auto, inf or keyframes SECONDS:METRES,..., got '" + text + "'");
  return *v;
}

Keyframes fNumberKeyframes(const std::string& text) {
  return parseKeyframes(
      "--fstop", text, [](double n) { return n >= 0.5 && n <= 1024.0; }, "an f-number from 0.5 to 1024");
}

Vec2d parseFocusPixel(const std::string& text) {
  const std::size_t comma = text.find(',');
  const auto x = comma == std::string::npos ? std::nullopt : parseDouble(text.substr(0, comma));
  const auto y = comma == std::string::npos ? std::nullopt : parseDouble(text.substr(comma + 1));
  if (!x || !y) throw UsageError("--focus-pixel", "expected X,Y in pixels, got '" + text + "'");
  return {*x, *y};
}

Vec2d parseSensor(const std::string& text) {
  if (const auto it = sensorNames().find(text); it != sensorNames().end()) return it->second;
  const std::size_t x = text.find_first_of("xX");
  const auto w = x == std::string::npos ? std::nullopt : parseDouble(text.substr(0, x));
  const auto h = x == std::string::npos ? std::nullopt : parseDouble(text.substr(x + 1));
  if (!w || !h || !(*w > 0.0) || !(*h > 0.0) || *w > 1000.0 || *h > 1000.0)
    throw UsageError("--sensor",
                     "expected WxH in mm (e.g. 36x24) or full-frame, aps-c, mft, 1in; got '" + text + "'");
  return {*w, *h};
}

namespace {

// Seconds >= 0 from "0.004", "1/250" or "2", for `flag`.
double parseSeconds(const std::string& text, const char* flag) {
  const std::size_t slash = text.find('/');
  std::optional<double> v;
  if (slash == std::string::npos) {
    v = parseDouble(text);
  } else {
    const auto a = parseDouble(text.substr(0, slash)), b = parseDouble(text.substr(slash + 1));
    if (a && b && *b > 0.0) v = *a / *b;
  }
  if (!v || !(*v >= 0.0) || *v > 1e6)
    throw UsageError(flag,
                     fmt::format("expected a time in seconds >= 0 (e.g. 0.01 or 1/100), got '{}'", text));
  return *v;
}

}  // namespace

double parseShutter(const std::string& text) {
  return parseSeconds(text, "--shutter");
}

double recordedSpanSeconds(const CameraOptions& o) {
  return shutterTiming(o).spanSeconds();
}

ShutterTiming shutterTiming(const CameraOptions& o) {
  ShutterTiming t;
  t.shutterSeconds = shutterSeconds(o);
  if (!o.rollingShutter.empty()) t.readoutSeconds = parseSeconds(o.rollingShutter, "--rolling-shutter");
  static const std::pair<const char*, ShutterTiming::Readout> kReadouts[] = {
      {"top-down", ShutterTiming::Readout::TopDown},
      {"bottom-up", ShutterTiming::Readout::BottomUp},
      {"left-right", ShutterTiming::Readout::LeftRight},
      {"right-left", ShutterTiming::Readout::RightLeft}};
  const auto readout = std::find_if(std::begin(kReadouts), std::end(kReadouts),
                                    [&](const auto& r) { return o.readout == r.first; });
  if (readout == std::end(kReadouts))
    throw UsageError(
        "--readout",
        fmt::format("expected top-down, bottom-up, left-right or right-left, got '{}'", o.readout));
  t.readout = readout->second;
  if (o.shutterCurve != "box") {
    const std::string prefix = "trapezoid:";
    const std::optional<double> f =
        o.shutterCurve.starts_with(prefix) ? parseDouble(o.shutterCurve.substr(prefix.size())) : std::nullopt;
    if (!f || !(*f > 0) || *f > 0.5)
      throw UsageError(
          "--shutter-curve",
          fmt::format("expected box or trapezoid:F with 0 < F <= 0.5 (the share of the interval the "
                      "shutter takes to open, and to close), got '{}'",
                      o.shutterCurve));
    t.rampFraction = *f;
  }
  return t;
}

FilmGeometry cameraFilm(const CameraOptions& options, int width, int height) {
  const Vec2d sensor = parseSensor(options.sensor);
  FilmGeometry f;
  f.width = width;
  f.height = height;
  const double aspect = double(width) / double(height);
  if (aspect >= sensor.x / sensor.y) {
    f.sensorWidthMm = sensor.x;
    f.sensorHeightMm = sensor.x / aspect;
  } else {
    f.sensorHeightMm = sensor.y;
    f.sensorWidthMm = sensor.y * aspect;
  }
  return f;
}

namespace {
std::unique_ptr<Camera> buildCamera(const CameraOptions& o, const CameraDesc& gltf, const FilmGeometry& film,
                                    const std::optional<LensPrescription>& lens, Warnings& warnings,
                                    const HitDistance& hitDistance);
}  // namespace

double shutterSeconds(const CameraOptions& o) {
  return o.shutter.empty() ? Exposure{}.shutterSeconds : parseShutter(o.shutter);
}

void checkCameraOptions(const CameraOptions& o) {
  const auto oneOf = [](const char* flag, const std::string& value,
                        std::initializer_list<const char*> names) {
    std::string list;
    for (const char* n : names) {
      if (value == n) return;
      list.append(list.empty() ? "" : ", ").append(n);
    }
    throw UsageError(flag, "expected one of " + list + ", got '" + value + "'");
  };
  const auto within = [](const char* flag, double v, double lo, double hi, const char* what) {
    if (!(v >= lo && v <= hi))
      throw UsageError(flag, fmt::format("{:g} is not in [{:g}, {:g}] ({})", v, lo, hi, what));
  };
  oneOf("--camera", o.model, {"pinhole", "thin", "thick", "lens"});
  if (o.fNumber) within("--fstop", *o.fNumber, 0.5, 1024.0, "the f-number");
  if (!o.fNumberKeyframes.empty()) fNumberKeyframes(o.fNumberKeyframes);
  parseFocus(o.focus);
  if (!o.focusPixel.empty()) parseFocusPixel(o.focusPixel);
  parseSensor(o.sensor);
  if (o.blades < 0 || o.blades > 64 || o.blades == 1 || o.blades == 2)
    throw UsageError("--blades", fmt::format("{} blades: an aperture needs 0 (round) or 3 to 64", o.blades));
  within("--blade-rotation", o.bladeRotationDegrees, -360.0, 360.0, "degrees");
  if (o.focalLengthMm) within("--focal-length", *o.focalLengthMm, 0.1, 10000.0, "mm");
  oneOf("--exposure", o.exposure, {"normalized", "physical"});
  if (!o.shutter.empty()) parseShutter(o.shutter);
  shutterTiming(o);
  if (o.exposure == "physical" && !(shutterSeconds(o) > 0))
    throw UsageError("--shutter", "--exposure physical records no light in a shutter time of 0");
  if (o.iso) within("--iso", *o.iso, 1.0, 1e7, "ISO speed");
  oneOf("--dispersion", o.dispersion, {"on", "off"});
  if (!o.coatings.empty()) oneOf("--coatings", o.coatings, {"none", "single", "multi"});
  oneOf("--flare", o.flare, {"on", "off"});
  if (o.flareBounces < 0 || o.flareBounces > 4 || o.flareBounces % 2 != 0)
    throw UsageError(
        "--flare-bounces",
        fmt::format("expected 0, 2 or 4 reflections (a ghost takes two), got {}", o.flareBounces));
  if (o.flare == "on" && o.model != "lens")
    throw UsageError("--flare", "stray light comes from the full lens's surfaces: it needs --camera lens");
  if (!(o.barrelReflectance >= 0.0 && o.barrelReflectance < 1.0))
    throw UsageError("--barrel-reflectance",
                     fmt::format("expected a reflectance in [0, 1), got {:g}", o.barrelReflectance));
  if (o.barrelReflectance > 0.0 && o.flare != "on")
    throw UsageError("--barrel-reflectance", "the barrel's stray light needs --flare on");
  if (!o.film.empty()) oneOf("--film", o.film, {"radiance", "irradiance"});
  oneOf("--spectral", o.spectral, {"on", "off"});
  checkColourOptions(o);
  oneOf("--noise", o.noise, {"on", "off"});
  if (o.noise == "off" && !o.sensorParams.empty())
    throw UsageError("--sensor-params", "describes the sensor's noise, which needs --noise on");
}

std::unique_ptr<Camera> makeCamera(const CameraOptions& o, const CameraDesc& gltf, FilmGeometry rasterFilm,
                                   const HitDistance& hitDistance, Warnings& warnings) {
  checkCameraOptions(o);
  const FilmGeometry film = cameraFilm(o, rasterFilm.width, rasterFilm.height);
  if (gltf.orthographic) {
    // Parallel rays are the pinhole model's radiance film without a lens; a
    // lens (or what a lens defines: a focal length, an exposure) makes a
    // perspective picture.
    const bool plain = o.model == "pinhole" && o.lens.empty() && !o.focalLengthMm && o.film != "irradiance" &&
                       o.exposure != "physical";
    if (plain) {
      const double aspect = double(film.width) / film.height, glTFAspect = double(gltf.xmag) / gltf.ymag;
      if (std::abs(aspect / glTFAspect - 1.0) > 0.01)
        warnings.warn(
            fmt::format("camera '{}' is orthographic with xmag/ymag {:.4g}, but the image's aspect "
                        "ratio is {:.4g}: keeping ymag, the view is {:.4g} m wide",
                        gltf.name, glTFAspect, aspect, 2.0 * gltf.ymag * aspect));
      return std::make_unique<OrthographicCamera>(gltf.worldFromCamera, film, gltf.ymag);
    }
    // One text whatever the model: `lensrt compare` makes four cameras and
    // warns once (Warnings drops repeats).
    warnings.warn("camera '" + gltf.name +
                  "' is orthographic; a lens model (thin, thick, lens), --lens, --focal-length or an "
                  "irradiance film renders it in perspective");
  }

  // Radiance film is the ideal pinhole's: a lens forms an image on a film, and
  // what reaches the film is irradiance (a mean radiance over the pupil would
  // hide the vignetting the lens models are there to show).
  const bool radianceFilm = o.film == "radiance" || (o.film.empty() && o.model == "pinhole");
  if (radianceFilm && o.model != "pinhole")
    throw UsageError("--film", "radiance film is the pinhole's; --camera " + o.model +
                                   " records film irradiance (--film irradiance, scaled by --exposure)");
  if (radianceFilm && o.exposure == "physical")
    throw UsageError("--exposure",
                     "physical exposure needs the irradiance film: add --film irradiance "
                     "(the pinhole's default film records radiance)");
  if (o.exposure != "physical" && o.iso)
    warnings.warn("--iso only applies with --exposure physical; ignored");

  // The lens, scaled to --focal-length when both are given.
  std::optional<UserLens> user;
  std::optional<LensPrescription> lens;
  if (!o.lens.empty()) {
    user = loadUserLens(o.lens, o.lensDir);
    requireRealImage(*user);
    if (o.focalLengthMm)
      user->prescription =
          user->prescription.scaled(*o.focalLengthMm / computeParaxial(user->prescription).efl);
    lens = user->prescription;
  } else if (o.model == "thick" || o.model == "lens") {
    throw UsageError("--lens", "--camera " + o.model + " needs a lens, e.g. --lens dgauss-50mm");
  }
  // Everything below that the optics reject is about the lens: name it.
  if (user)
    return withLensErrors(*user, [&] { return buildCamera(o, gltf, film, lens, warnings, hitDistance); });
  return buildCamera(o, gltf, film, lens, warnings, hitDistance);
}

namespace {

std::unique_ptr<Camera> buildCamera(const CameraOptions& o, const CameraDesc& gltf, const FilmGeometry& film,
                                    const std::optional<LensPrescription>& lens, Warnings& warnings,
                                    const HitDistance& hitDistance) {
  const Transform& worldFromCamera = gltf.worldFromCamera;
  Exposure exposure;
  exposure.mode = o.exposure == "physical" ? ExposureMode::Physical : ExposureMode::Normalized;
  exposure.shutterSeconds = shutterSeconds(o);
  if (o.iso) exposure.iso = *o.iso;
  const std::optional<ParaxialData> paraxial = lens ? std::optional(computeParaxial(*lens)) : std::nullopt;
  const std::optional<double> keyedFNumber =
      o.fNumberKeyframes.empty()
          ? o.fNumber
          : std::optional<double>(valueAt(fNumberKeyframes(o.fNumberKeyframes), o.timeSeconds));
  const double fNumber = keyedFNumber ? *keyedFNumber : paraxial ? paraxial->fNumber : 2.8;
  const ApertureShape aperture{o.blades, o.bladeRotationDegrees};

  // Focal length and the infinity-focus field of view without a lens.
  const double yfovGltf = gltf.yfov;
  const double focalMm = paraxial          ? paraxial->efl
                         : o.focalLengthMm ? *o.focalLengthMm
                                           : 0.5 * film.sensorHeightMm / std::tan(0.5 * yfovGltf);
  const double yfovInfinity =
      paraxial || o.focalLengthMm ? 2.0 * std::atan(0.5 * film.sensorHeightMm / focalMm) : yfovGltf;

  // The closest focus: the lens's own (its file's, else magnification 1:1),
  // the same for all four models derived from it so that they stay
  // comparable; an ideal thin lens without one stops at 1:1 too (2f).
  const double closestMm = lens ? closestFocusDistanceMm(LensSystem(*lens)) : 2.0 * focalMm;
  const std::string optic = o.model == "thin" ? fmt::format("the thin lens (f = {:.4g} mm)", focalMm)
                            : lens            ? lens->name
                                              : "the lens";

  // Focus: what the chosen pixel sees, measured along the axis.
  std::optional<double> focus = parseFocus(o.focus, o.timeSeconds);
  if (!o.focusPixel.empty() && focus) throw UsageError("--focus-pixel", "only applies with --focus auto");
  const bool needsFocus = o.model != "pinhole" || lens.has_value();
  if (!focus && needsFocus) {
    Vec2d pixel{film.width / 2.0, film.height / 2.0};
    if (!o.focusPixel.empty()) {
      pixel = parseFocusPixel(o.focusPixel);
      if (pixel.x < 0 || pixel.y < 0 || pixel.x >= film.width || pixel.y >= film.height)
        throw UsageError("--focus-pixel", fmt::format("{},{} is outside the {}x{} image", pixel.x, pixel.y,
                                                      film.width, film.height));
      pixel = {pixel.x + 0.5, pixel.y + 0.5};
    }
    const PinholeCamera aim(worldFromCamera, film, yfovInfinity);
    CameraSample s;
    s.film = {float(pixel.x), float(pixel.y)};
    const auto ray = aim.generateRay(s);
    const std::optional<double> hit = hitDistance && ray ? hitDistance(ray->ray) : std::nullopt;
    if (hit && *hit > 0.0 && std::isfinite(*hit)) {
      // The pinhole ray's direction in camera space has z = -1: axial distance = t cos.
      const double tanX =
          (2.0 * pixel.x / film.width - 1.0) * std::tan(0.5 * yfovInfinity) * film.width / film.height;
      const double tanY = (1.0 - 2.0 * pixel.y / film.height) * std::tan(0.5 * yfovInfinity);
      focus = *hit / std::sqrt(1.0 + tanX * tanX + tanY * tanY);
    } else {
      warnings.warn("--focus auto: the focus pixel sees no surface; focusing at infinity");
      focus = kInfinity;
    }
    // Too close for the optics: focus as close as they can.
    const double closestM = closestMm / 1000.0;
    if (*focus < closestM) {
      warnings.warn(
          fmt::format("--focus auto: the surface at {:.4g} m is closer than {} focuses; focusing at its "
                      "closest, {:.4g} m",
                      *focus, lens ? lens->name : optic, closestM));
      focus = closestM;
    }
  }
  const double focusM = focus.value_or(kInfinity);
  if (needsFocus && !std::isinf(focusM) && focusM * 1000.0 < closestMm * (1 - 1e-12))
    throw UsageError("--focus", fmt::format("{} cannot focus at {:g} m (its closest focus is {:.4g} m)",
                                            optic, focusM, closestMm / 1000.0));

  // What the camera models still reject is about the lens (makeCamera names
  // it) or the glTF camera (RenderJob names the scene).
  const std::string lensName = lens ? lens->name : "";
  if (!o.apertureMask.empty() && o.model != "lens")
    throw UsageError("--aperture-mask", "needs --camera lens (the mask sits at the lens's stop)");
  if (o.model == "pinhole") {
    const double yfov = paraxial ? lensVerticalFov(*paraxial, focusM, film.sensorHeightMm) : yfovInfinity;
    if (o.film == "irradiance")
      return std::make_unique<PinholeCamera>(worldFromCamera, film, yfov, exposure, fNumber, lensName);
    return std::make_unique<PinholeCamera>(worldFromCamera, film, yfov, lensName);
  }
  if (o.model == "thin") {
    ThinLensParams p;
    p.focalLengthMm = focalMm;
    p.fNumber = fNumber;
    p.focusMetres = focusM;
    p.aperture = aperture;
    p.lensName = lensName;
    if (lens && o.dispersion == "on" && hasDispersion(*lens)) p.dispersion.emplace(*lens);
    return std::make_unique<ThinLensCamera>(worldFromCamera, film, p, exposure);
  }
  if (o.model == "thick") {
    if (keyedFNumber && *keyedFNumber < paraxial->fNumber * (1 - 1e-9))
      warnings.warn(fmt::format("{}: f/{:g} is wider than the lens allows; the thick lens opens to it anyway",
                                lensName, *keyedFNumber));
    ThickLensParams p = thickLensFromParaxial(*paraxial, fNumber, focusM);
    p.aperture = aperture;
    p.lensName = lensName;
    if (o.dispersion == "on" && hasDispersion(*lens)) p.dispersion.emplace(*lens);
    return std::make_unique<ThickLensCamera>(worldFromCamera, film, p, exposure);
  }
  LensCameraParams p;
  if (!o.apertureMask.empty()) {
    if (o.blades) throw UsageError("--aperture-mask", "replaces --blades: give one of them");
    p.mask = std::make_shared<const ApertureMask>(readApertureMask(o.apertureMask));
  }
  p.fNumber = fNumber;
  p.focusMetres = focusM;
  p.aperture = aperture;
  p.dispersion = o.dispersion == "on";
  p.coatings = parseCoating(o.coatings);
  if (o.flare == "on") {
    p.flareReflections = o.flareBounces;
    p.barrelReflectance = o.barrelReflectance;
    // Stray light needs reflecting surfaces: bare glass unless --coatings says otherwise.
    if (!p.coatings) p.coatings = Coating::None;
  }
  return std::make_unique<LensCamera>(worldFromCamera, film, *lens, p, exposure, warnings);
}

// Sixteen numbers, row by row, to float precision and more.
std::string matrixText(const Transform::Matrix& m) {
  std::string s;
  for (const auto& row : m)
    for (const double v : row) s += fmt::format("{}{:.9g}", s.empty() ? "" : " ", v);
  return s;
}

}  // namespace

ImageMetadata standardCameraAttributes(const Camera& camera) {
  const CameraInfo i = camera.info();
  ImageMetadata m;
  if (i.fNumber > 0) m["aperture"] = fmt::format("{:.6g}", i.fNumber);
  if (i.focusMetres > 0 && std::isfinite(i.focusMetres)) m["focus"] = fmt::format("{:.6g}", i.focusMetres);
  double shutter = 0.0, iso = 0.0;
  if (std::sscanf(i.exposure.c_str(), "physical %lgs ISO%lg", &shutter, &iso) == 2) {
    m["expTime"] = fmt::format("{:.6g}", shutter);
    m["isoSpeed"] = fmt::format("{:.6g}", iso);
  }
  // OpenEXR's camera space is left-handed, looking down +Z with +Y up; glTF's
  // looks down -Z: negate z after the world-to-camera transform. Imath
  // multiplies row vectors, so the matrix is stored transposed.
  const Transform::Matrix w = camera.worldFromCamera().inverse().matrix();
  std::string text;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      text += fmt::format("{}{:.9g}", text.empty() ? "" : " ", (r == 2 ? -1.0 : 1.0) * w[r][c]);
  m["worldToCamera"] = text;
  // The film's RGB: linear Rec.709 primaries, D65 white (as sRGB).
  m["chromaticities"] = "0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329";
  return m;
}

ImageMetadata cameraMetadata(const Camera& camera) {
  const CameraInfo i = camera.info();
  const FilmGeometry& f = camera.film();
  ImageMetadata standard = standardCameraAttributes(camera);
  ImageMetadata m = {
      {"lensrt:camera_model", i.model},
      {"lensrt:lens", i.lens.empty() ? "none" : i.lens},
      {"lensrt:f_number", i.fNumber > 0 ? fmt::format("{:.3g}", i.fNumber) : "none"},
      {"lensrt:focus_m", i.focusMetres > 0 ? metresText(i.focusMetres) : "none"},
      {"lensrt:focal_length_mm", fmt::format("{:.4g}", i.focalLengthMm)},
      {"lensrt:sensor_mm", fmt::format("{:.4g}x{:.4g}", f.sensorWidthMm, f.sensorHeightMm)},
      {"lensrt:exposure", i.exposure},
      {"lensrt:coatings", i.coatings.empty() ? "off (lossless)" : i.coatings},
      // Where the camera stood, so another renderer can take the same view
      // (tools/validate-cycles does): glTF world space, metres, row by row.
      {"lensrt:world_from_camera", matrixText(camera.worldFromCamera().matrix())},
      {"lensrt:dispersion", i.dispersion ? "on" : "off"},
      {"lensrt:film", i.film},
  };
  m.merge(standard);
  return m;
}

}  // namespace lensrt
