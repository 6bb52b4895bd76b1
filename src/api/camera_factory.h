// The camera a spec asks for (api/camera_spec.h), framed by the glTF camera:
// one of the models of api/camera_models.h, with the lens loaded, the focus
// found and the exposure set.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "api/camera_spec.h"
#include "api/flare_spec.h"
#include "api/shutter_spec.h"
#include "camera/camera.h"
#include "camera/exposure.h"
#include "camera/lens_camera.h"
#include "core/ray.h"
#include "core/warnings.h"
#include "image/image.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The film: the sensor cropped to the raster's aspect ratio (square pixels),
// as a camera's video or crop modes do.
FilmGeometry cameraFilm(const Vec2d& sensorMm, int width, int height);

// The distance (metres, along the unit world-space ray) to the first surface
// the ray hits; nullopt when it hits nothing. Used for --focus auto.
using HitDistance = std::function<std::optional<double>(const Ray&)>;

// What a camera is made of besides the glTF camera.
struct CameraRequest {
  const CameraSpec& camera;
  const ShutterSpec& shutter;
  const FlareSpec& flare;
  double timeSeconds = 0.0;  // when the shutter opens: where keyframed settings are read
};

// The camera settings' checks across rows that hold for every model (an
// aperture mask or blades; a focus pixel only with auto focus): part of
// checkSpec, and of makeCamera for callers that make cameras directly.
// Throws UsageError.
void checkCameraSpec(const CameraSpec& camera);

// The exposure the spec asks for (the shutter's time, the ISO).
Exposure cameraExposure(const CameraSpec& camera, const ShutterSpec& shutter);

// Builds the model. `raster` gives the raster size; its sensor is the spec's.
// With a lens the simpler models are derived from its paraxial data (thin: f
// = EFL and its f-number; thick: its cardinal points and pupils; pinhole: the
// lens's field of view at that focus). Without one, f is the focal length
// asked for, else the glTF camera's yfov over the sensor height.
// `flareLens`, when given, is set to the full lens when it makes stray light.
// Throws UsageError and InputError.
std::unique_ptr<Camera> makeCamera(const CameraRequest& request, const CameraDesc& gltfCamera,
                                   FilmGeometry raster, const HitDistance& hitDistance, Warnings& warnings,
                                   const LensCamera** flareLens = nullptr);

// lensrt:camera_model, lensrt:lens, lensrt:f_number, lensrt:focus_m,
// lensrt:focal_length_mm, lensrt:sensor_mm, lensrt:exposure, lensrt:dispersion,
// lensrt:coatings, lensrt:film, and OpenEXR's standard attributes, which the
// image layer writes typed: aperture (f-number), focus (m), expTime (s) and
// isoSpeed (physical exposure only), worldToCamera, chromaticities (Rec.709, D65).
ImageMetadata cameraMetadata(const Camera& camera, const Exposure& exposure);
ImageMetadata standardCameraAttributes(const Camera& camera, const Exposure& exposure);

}  // namespace lensrt
