#include "api/standalone_camera.h"

#include <fmt/core.h>

#include "api/camera_factory.h"
#include "api/flare_spec.h"
#include "api/shutter_spec.h"
#include "core/error.h"
#include "scene/scene_desc.h"

namespace lensrt {

StandaloneCamera makeStandaloneCamera(const CameraSpec& spec, int width, int height,
                                      const Transform& worldFromCamera, Warnings& warnings) {
  if (width < 2 || height < 2 || width > 65536 || height > 65536)
    throw UsageError("--res", fmt::format("expected 2x2 to 65536x65536 pixels, got {}x{}", width, height));
  if (!spec.focusMetres || !spec.focusKeys.empty())
    throw UsageError("--focus",
                     "expected a distance in metres or inf: 'auto' measures a scene, and there is none");
  if (!spec.fNumberKeys.empty()) throw UsageError("--fstop", "expected one f-number, not keyframes");
  if (spec.fNumber && !(*spec.fNumber >= 0.5 && *spec.fNumber <= 1024.0))
    throw UsageError(
        "--fstop", fmt::format("expected a number from 0.5 to 1024 (the f-number), got {:g}", *spec.fNumber));
  FilmGeometry film;
  film.width = width;
  film.height = height;
  CameraDesc desc;
  desc.worldFromCamera = worldFromCamera;
  const ShutterSpec shutter;
  const FlareSpec flare;
  return {makeCamera(CameraRequest{spec, shutter, flare}, desc, film, {}, warnings), *spec.focusMetres};
}

}  // namespace lensrt
