// One interface for the four camera models (pinhole, thin, thick, full lens).
// Samples come from outside (keyed by seed, pixel and sample index), so every
// model is deterministic and knows nothing about threads or tiles.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "camera/lens_movements.h"
#include "camera/projection.h"
#include "camera/stop_diffraction.h"
#include "core/ray.h"
#include "core/transform.h"
#include "core/vec.h"

namespace lensrt {

// Conventions (documented in the README):
//  - Raster space: pixel (0,0) is the top-left corner, x right, y down, in pixels.
//  - Camera space: glTF's, right-handed, looking down -Z with +Y up, metres. The
//    origin is the lens's entrance pupil (centre of perspective).
//  - Sensor: physical width x height in millimetres, mapped onto the full raster.
struct FilmGeometry {
  int width = 640;            // pixels
  int height = 360;           // pixels
  double sensorWidthMm = 36;  // physical film size
  double sensorHeightMm = 24;
};

struct CameraSample {
  Vec2f film;                     // raster position in pixels, continuous
  Vec2f lens;                     // uniform in [0,1)^2: aperture / exit-pupil sample
  float wavelengthNm = 550.f;     // nm: the wavelength a dispersive camera traces this sample at
  Vec2f diffraction{0.5f, 0.5f};  // uniform in [0,1)^2: the far-field bend (--diffraction on only)
  // Spectral transport through a camera that carriesLanes(): the other three
  // wavelengths (nm) the path carries past the lens; 0: none asked.
  std::array<float, 3> secondaryNm{};
};

struct CameraRay {
  Ray ray;              // world space, unit direction
  float weight = 1.0f;  // multiplies the radiance: irradiance estimate scaled by exposure
  // --flare on: the ray reflected in the lens (or scattered off its barrel)
  // on its way out; the flare light pass takes such paths of the sources it
  // handles, so the integrator skips those (render/flare_light_pass.h).
  bool lensReflected = false;
  // Asked for with CameraSample::secondaryNm: each wavelength's factor on
  // `weight` (the hero's first), from multiple importance sampling over the
  // four wavelengths as hero (camera/wavelength_lanes.h); 0 for a wavelength
  // whose trace of the same outgoing ray misses the sample's pixel.
  std::optional<std::array<float, 4>> laneWeights = std::nullopt;
};

// Radiometry shared by the models (see exposure.h for the exposure modes):
// the film records irradiance E = integral of L cos(th_film) cos(th_pupil) /
// d^2 over the pupil, and a ray's weight is that integrand over its sampling
// pdf, times the exposure scale. So the thin lens obeys the seed's
// E = L pi cos^4(theta) / (4 N^2) (focused at infinity; A cos^4 / Q^2 at a
// finite focus) and the full lens shows natural and optical vignetting.

// What a camera is, for metadata and reports.
struct CameraInfo {
  std::string model;         // "pinhole", "thin", "thick", "lens"
  std::string lens;          // lens name the model was derived from; empty without one
  double fNumber = 0.0;      // 0: no aperture (pinhole)
  double focusMetres = 0.0;  // from the entrance pupil; +infinity at infinity; 0: none (pinhole)
  double focalLengthMm = 0.0;
  std::string exposure;       // e.g. "normalized" or "physical 0.01s ISO100"
  bool dispersion = false;    // each sample traced at its own wavelength (tracesWavelengths)
  std::string coatings = {};  // the full lens's Fresnel model: "none", "single", "multi"; empty: lossless
  // What a pixel records: "irradiance" (the physical film: cos^4, bellows
  // factor, exposure scale) or "radiance" (the mean radiance along the camera
  // rays: only the ideal pinhole offers it, as pbrt, Cycles and Mitsuba do).
  std::string film = "irradiance";
  LensMovements movements = {};  // the film's shift and tilt (lens_movements.h); none by default
  // Along the axis from the film to the entrance pupil (camera space's
  // origin), mm, positive toward the scene (OpenEXR's entrancePupilOffset);
  // 0: none (orthographic).
  double entrancePupilOffsetMm = 0.0;
};

// A focus distance for describe(): "2m", "infinity".
inline std::string focusText(double metres) {
  if (std::isinf(metres)) return "infinity";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%gm", metres);
  return buf;
}

class Camera {
 public:
  Camera(const Transform& worldFromCamera, const FilmGeometry& film)
      : worldFromCamera_(worldFromCamera),
        cameraFromWorld_(worldFromCamera.invertible() ? worldFromCamera.inverse() : Transform()),
        film_(film) {}
  virtual ~Camera() = default;
  Camera(const Camera&) = delete;
  Camera& operator=(const Camera&) = delete;

  // Empty when the optics block the ray (vignetting): the sample contributes zero.
  std::optional<CameraRay> generateRay(const CameraSample& sample) const {
    std::optional<CameraRay> r = generateCameraSpaceRay(sample);
    if (diffraction_) diffract(r, sample);
    if (!r) return std::nullopt;
    r->ray = worldFromCamera_(r->ray);
    r->ray.direction = normalize(r->ray.direction);
    return r;
  }

  // generateRay for each sample, in one call: a model may trace them together
  // (the full lens does, several times faster). The same rays, bit for bit.
  void generateRays(std::span<const CameraSample> samples, std::span<std::optional<CameraRay>> out) const {
    generateCameraSpaceRays(samples, out);
    if (diffraction_)
      for (std::size_t i = 0; i < samples.size(); ++i) diffract(out[i], samples[i]);
    for (std::optional<CameraRay>& r : out)
      if (r) {
        r->ray = worldFromCamera_(r->ray);
        r->ray.direction = normalize(r->ray.direction);
      }
  }

  // True when rays depend on CameraSample::wavelengthNm (dispersion): the
  // renderer then weights each sample's RGB by its wavelength's response.
  virtual bool tracesWavelengths() const { return false; }
  // True when the camera, tracing wavelengths, can weigh the secondary
  // wavelengths of a spectral sample (CameraSample::secondaryNm), so that a
  // path carries all four past the lens instead of its hero alone.
  virtual bool carriesLanes() const { return false; }
  // --diffraction on: every ray is bent by the stop's far field at its
  // sample's wavelength (CameraSample::diffraction), so the renderer gives
  // each sample a wavelength, as for dispersion.
  bool diffracts() const { return diffraction_ != nullptr; }

  // Model name and parameters for EXR metadata and reports, e.g. "pinhole yfov=39.6deg".
  virtual std::string describe() const = 0;
  virtual CameraInfo info() const = 0;

  const Transform& worldFromCamera() const { return worldFromCamera_; }
  const FilmGeometry& film() const { return film_; }

  // The projection (camera/projection.h): where a camera-space point (metres)
  // images in raster pixels at a wavelength (nm), and the ray a raster
  // position sees, in camera space. Thread-safe and deterministic. A moved
  // film (--shift, --tilt) is met where the chief ray's image side crosses it.
  virtual ProjectedPoint projectCameraPoint(const Vec3d& point, double wavelengthNm) const = 0;
  // The same, where the full lens starts its chief-ray solve from `hint`
  // (a nearby point's, optics/chief_ray_hint.h) and leaves its own there;
  // the other models' projections are closed forms that ignore it.
  virtual ProjectedPoint projectCameraPointHinted(const Vec3d& point, double wavelengthNm,
                                                  ChiefRayHint*) const {
    return projectCameraPoint(point, wavelengthNm);
  }
  virtual ProjectedRay unprojectRaster(const Vec2d& raster, double wavelengthNm) const = 0;
  // The same in world space, through this camera's pose (a moving camera's
  // caller applies the pose of the moment to projectCameraPoint instead).
  ProjectedPoint project(const Vec3d& worldPoint, double wavelengthNm) const {
    return projectCameraPoint(cameraFromWorld_.point(worldPoint), wavelengthNm);
  }
  ProjectedRay unproject(const Vec2d& raster, double wavelengthNm) const {
    ProjectedRay r = unprojectRaster(raster, wavelengthNm);
    r.origin = worldFromCamera_.point(r.origin);
    r.direction = normalize(worldFromCamera_.vector(r.direction));
    return r;
  }

 protected:
  // Ray in camera space (origin in metres, any direction length).
  virtual std::optional<CameraRay> generateCameraSpaceRay(const CameraSample& sample) const = 0;
  // A model with an aperture turns --diffraction on by giving its stop.
  void setDiffraction(std::shared_ptr<const StopDiffraction> diffraction) {
    diffraction_ = std::move(diffraction);
  }
  // out.size() == samples.size(). By default one at a time.
  virtual void generateCameraSpaceRays(std::span<const CameraSample> samples,
                                       std::span<std::optional<CameraRay>> out) const {
    for (std::size_t i = 0; i < samples.size(); ++i) out[i] = generateCameraSpaceRay(samples[i]);
  }

 private:
  Transform worldFromCamera_;
  Transform cameraFromWorld_;  // identity when the pose is singular (it then renders nothing sensible either)
  std::shared_ptr<const StopDiffraction> diffraction_;  // none: geometric rays

  void diffract(std::optional<CameraRay>& r, const CameraSample& sample) const {
    if (!r) return;
    const std::optional<Vec3f> bent =
        diffraction_->bend(normalize(r->ray.direction), sample.diffraction, sample.wavelengthNm);
    if (bent)
      r->ray.direction = *bent;
    else
      r.reset();
  }
  FilmGeometry film_;
};

}  // namespace lensrt
