#include "api/camera_factory.h"

#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <string>

#include "api/camera_models.h"
#include "api/keyframes.h"
#include "api/lens_loading.h"
#include "camera/orthographic_camera.h"
#include "camera/pinhole_camera.h"
#include "core/constants.h"
#include "core/error.h"
#include "optics/focus.h"
#include "optics/glass.h"
#include "optics/lens_readers.h"
#include "optics/paraxial.h"

namespace lensrt {
namespace {

std::string metresText(double m) {
  return std::isinf(m) ? "inf" : fmt::format("{:.4g}", m);
}

std::unique_ptr<Camera> buildCamera(const CameraRequest& request, const CameraDesc& gltf,
                                    const FilmGeometry& film, const std::optional<LensPrescription>& lens,
                                    Warnings& warnings, const HitDistance& hitDistance,
                                    const LensCamera** flareLens);

}  // namespace

std::filesystem::path CameraSpec::defaultLensDir() {
#ifdef LENSRT_LENS_DIR
  return LENSRT_LENS_DIR;
#else
  return {};
#endif
}

FilmGeometry cameraFilm(const Vec2d& sensor, int width, int height) {
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

void checkCameraSpec(const CameraSpec& c) {
  if (!c.apertureMask.empty() && c.blades)
    throw UsageError("--aperture-mask", "replaces --blades: give one of them");
  if (c.focusPixel && !c.autoFocus()) throw UsageError("--focus-pixel", "only applies with --focus auto");
}

Exposure cameraExposure(const CameraSpec& c, const ShutterSpec& shutter) {
  Exposure exposure;
  exposure.mode = c.exposure;
  exposure.shutterSeconds = shutter.shutterSeconds();
  if (c.iso) exposure.iso = *c.iso;
  return exposure;
}

std::unique_ptr<Camera> makeCamera(const CameraRequest& request, const CameraDesc& gltf,
                                   FilmGeometry rasterFilm, const HitDistance& hitDistance,
                                   Warnings& warnings, const LensCamera** flareLens) {
  const CameraSpec& o = request.camera;
  checkCameraSpec(o);
  const FilmGeometry film = cameraFilm(o.sensorMm, rasterFilm.width, rasterFilm.height);
  const bool pinhole = o.model == CameraModel::Pinhole;
  if (gltf.orthographic) {
    // Parallel rays are the pinhole model's radiance film without a lens; a
    // lens (or what a lens defines: a focal length, an exposure) makes a
    // perspective picture.
    const bool plain = pinhole && o.lens.empty() && !o.focalLengthMm && o.film != FilmQuantity::Irradiance &&
                       o.exposure != ExposureMode::Physical;
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
  const bool radianceFilm = o.film == FilmQuantity::Radiance || (!o.film && pinhole);
  if (radianceFilm && !pinhole)
    throw UsageError("--film", "radiance film is the pinhole's; --camera " + cameraModelName(o.model) +
                                   " records film irradiance (--film irradiance, scaled by --exposure)");
  if (radianceFilm && o.exposure == ExposureMode::Physical)
    throw UsageError("--exposure",
                     "physical exposure needs the irradiance film: add --film irradiance "
                     "(the pinhole's default film records radiance)");

  // The lens, scaled to the focal length when both are given.
  std::optional<UserLens> user;
  std::optional<LensPrescription> lens;
  if (!o.lens.empty()) {
    user = loadUserLens(o.lens, o.lensDir);
    requireRealImage(*user);
    if (o.focalLengthMm)
      user->prescription =
          user->prescription.scaled(*o.focalLengthMm / computeParaxial(user->prescription).efl);
    lens = user->prescription;
  } else if (cameraModel(o.model).needsLens) {
    throw UsageError("--lens",
                     "--camera " + cameraModelName(o.model) + " needs a lens, e.g. --lens dgauss-50mm");
  }
  // Everything below that the optics reject is about the lens: name it.
  if (user)
    return withLensErrors(
        *user, [&] { return buildCamera(request, gltf, film, lens, warnings, hitDistance, flareLens); });
  return buildCamera(request, gltf, film, lens, warnings, hitDistance, flareLens);
}

namespace {

std::unique_ptr<Camera> buildCamera(const CameraRequest& request, const CameraDesc& gltf,
                                    const FilmGeometry& film, const std::optional<LensPrescription>& lens,
                                    Warnings& warnings, const HitDistance& hitDistance,
                                    const LensCamera** flareLens) {
  const CameraSpec& o = request.camera;
  const Transform& worldFromCamera = gltf.worldFromCamera;
  const Exposure exposure = cameraExposure(o, request.shutter);
  const std::optional<ParaxialData> paraxial = lens ? std::optional(computeParaxial(*lens)) : std::nullopt;
  const std::optional<double> keyedFNumber =
      o.fNumberKeys.empty() ? o.fNumber : std::optional<double>(valueAt(o.fNumberKeys, request.timeSeconds));
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
  const std::string optic = o.model == CameraModel::Thin
                                ? fmt::format("the thin lens (f = {:.4g} mm)", focalMm)
                            : lens ? lens->name
                                   : "the lens";

  // Focus: what the chosen pixel sees, measured along the axis.
  std::optional<double> focus =
      o.focusKeys.empty() ? o.focusMetres : std::optional<double>(valueAt(o.focusKeys, request.timeSeconds));
  const bool needsFocus = o.model != CameraModel::Pinhole || lens.has_value();
  if (!focus && needsFocus) {
    Vec2d pixel{film.width / 2.0, film.height / 2.0};
    if (o.focusPixel) {
      pixel = *o.focusPixel;
      if (pixel.x < 0 || pixel.y < 0 || pixel.x >= film.width || pixel.y >= film.height)
        throw UsageError("--focus-pixel", fmt::format("{},{} is outside the {}x{} image", pixel.x, pixel.y,
                                                      film.width, film.height));
      pixel = {pixel.x + 0.5, pixel.y + 0.5};
    }
    // The film's shift moves what the pixel sees (the tilt only what is sharp).
    LensMovements shift;
    shift.shiftMm = o.movements.shiftMm;
    const PinholeCamera aim(worldFromCamera, film, yfovInfinity, {}, shift);
    CameraSample s;
    s.film = {float(pixel.x), float(pixel.y)};
    const auto ray = aim.generateRay(s);
    const std::optional<double> hit = hitDistance && ray ? hitDistance(ray->ray) : std::nullopt;
    if (hit && *hit > 0.0 && std::isfinite(*hit)) {
      // The pinhole ray's direction in camera space has z = -1: axial distance = t cos.
      const double perMm = std::tan(0.5 * yfovInfinity) / (0.5 * film.sensorHeightMm);
      const double tanX =
          (2.0 * pixel.x / film.width - 1.0) * std::tan(0.5 * yfovInfinity) * film.width / film.height +
          shift.shiftMm.x * perMm;
      const double tanY =
          (1.0 - 2.0 * pixel.y / film.height) * std::tan(0.5 * yfovInfinity) + shift.shiftMm.y * perMm;
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
  if (const std::optional<std::string> problem = lensMovementsProblem(o.movements, film))
    throw UsageError(problem->find("tilt") != std::string::npos ? "--tilt" : "--shift", *problem);
  const CameraBuild build{o,        request.flare,          worldFromCamera, film,     exposure,     lens,
                          paraxial, keyedFNumber,           fNumber,         focalMm,  yfovInfinity, focusM,
                          aperture, lens ? lens->name : "", o.movements,     warnings, flareLens};
  return cameraModel(o.model).create(build);
}

// Sixteen numbers, row by row, to float precision and more.
std::string matrixText(const Transform::Matrix& m) {
  std::string s;
  for (const auto& row : m)
    for (const double v : row) s += fmt::format("{}{:.9g}", s.empty() ? "" : " ", v);
  return s;
}

// OpenEXR's worldToNDC (Imath's row-vector order, as worldToCamera): NDC
// (0, 0) is the image's top left corner, (1, 1) its bottom right, and after
// the divide by w (OpenEXR's camera z, the depth along the axis) x and y are
// the paraxial (distortion-free) projection, z is 1 / depth. The projection's
// centre and scale come from the camera's own projection of points near the
// axis at the focus distance (10 m for the pinhole or at infinity), so the
// matrix is the pinhole that matches the lens at the image's centre; a
// shifted film moves that centre. None for a tilted film (its image is no
// longer a scaled copy of the scene's perspective about the axis: a
// 4 x 4 matrix with w the depth cannot hold it) or a projection that fails.
std::optional<std::string> worldToNdcText(const Camera& camera, const Transform::Matrix& cameraFromWorld) {
  const CameraInfo i = camera.info();
  const FilmGeometry& film = camera.film();
  if (i.movements.tilted() || i.entrancePupilOffsetMm <= 0 || film.width <= 0 || film.height <= 0)
    return std::nullopt;
  const double depth = i.focusMetres > 0 && std::isfinite(i.focusMetres) ? i.focusMetres : 10.0;
  constexpr double kTan = 1e-3;
  const auto raster = [&](double tx, double ty) {
    return camera.projectCameraPoint(Vec3d{tx * depth, ty * depth, -depth}, kWavelengthDNm).raster;
  };
  const Vec2d c = raster(0, 0);
  const double fx = (raster(kTan, 0).x - raster(-kTan, 0).x) / (2 * kTan);
  const double fy = (raster(0, -kTan).y - raster(0, kTan).y) / (2 * kTan);  // raster y runs down
  if (!std::isfinite(c.x) || !std::isfinite(c.y) || !(fx > 0) || !(fy > 0)) return std::nullopt;
  // NDC from OpenEXR camera space (x right, y up, z ahead), row vectors:
  // (x fx / W + z cx / W, -y fy / H + z cy / H, 1, z).
  double ndc[4][4] = {};
  ndc[0][0] = fx / film.width;
  ndc[2][0] = c.x / film.width;
  ndc[1][1] = -fy / film.height;
  ndc[2][1] = c.y / film.height;
  ndc[3][2] = 1;
  ndc[2][3] = 1;
  std::string text;
  for (int r = 0; r < 4; ++r)
    for (int col = 0; col < 4; ++col) {
      // worldToCamera in row-vector form is (S w)^T, S negating z (see below).
      double v = 0;
      for (int k = 0; k < 4; ++k) v += (k == 2 ? -1.0 : 1.0) * cameraFromWorld[k][r] * ndc[k][col];
      text += fmt::format("{}{:.9g}", text.empty() ? "" : " ", v);
    }
  return text;
}

}  // namespace

ImageMetadata standardCameraAttributes(const Camera& camera, const Exposure& exposure) {
  const CameraInfo i = camera.info();
  ImageMetadata m;
  if (i.fNumber > 0) m["aperture"] = fmt::format("{:.6g}", i.fNumber);
  if (i.focusMetres > 0 && std::isfinite(i.focusMetres)) m["focus"] = fmt::format("{:.6g}", i.focusMetres);
  if (exposure.mode == ExposureMode::Physical && i.film == "irradiance") {
    m["expTime"] = fmt::format("{:.6g}", exposure.shutterSeconds);
    m["isoSpeed"] = fmt::format("{:.6g}", exposure.iso);
  }
  // OpenEXR 3.2's lens and sensor attributes (floats in mm and microns, the
  // lens a string): what a compositor's match move reads.
  if (!i.lens.empty()) m["lensModel"] = i.lens;
  if (i.focalLengthMm > 0) {
    m["effectiveFocalLength"] = fmt::format("{:.6g}", i.focalLengthMm);
    // The barrel's figure: the design's focal length in whole millimetres.
    m["nominalFocalLength"] = fmt::format("{:.0f}", i.focalLengthMm);
  }
  const FilmGeometry& film = camera.film();
  if (film.width > 0)
    m["sensorPhotositePitch"] = fmt::format("{:.6g}", film.sensorWidthMm * 1000.0 / film.width);
  m["sensorOverallDimensions"] = fmt::format("{:.6g} {:.6g}", film.sensorWidthMm, film.sensorHeightMm);
  // OpenEXR's camera space is left-handed, looking down +Z with +Y up; glTF's
  // looks down -Z: negate z after the world-to-camera transform. Imath
  // multiplies row vectors, so the matrix is stored transposed.
  const Transform::Matrix w = camera.worldFromCamera().inverse().matrix();
  std::string text;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      text += fmt::format("{}{:.9g}", text.empty() ? "" : " ", (r == 2 ? -1.0 : 1.0) * w[r][c]);
  m["worldToCamera"] = text;
  if (i.entrancePupilOffsetMm > 0) m["entrancePupilOffset"] = fmt::format("{:.6g}", i.entrancePupilOffsetMm);
  if (const std::optional<std::string> ndc = worldToNdcText(camera, w)) m["worldToNDC"] = *ndc;
  // The film's RGB: linear Rec.709 primaries, D65 white (as sRGB).
  m["chromaticities"] = "0.64 0.33 0.3 0.6 0.15 0.06 0.3127 0.329";
  return m;
}

ImageMetadata cameraMetadata(const Camera& camera, const Exposure& exposure) {
  const CameraInfo i = camera.info();
  const FilmGeometry& f = camera.film();
  ImageMetadata standard = standardCameraAttributes(camera, exposure);
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
