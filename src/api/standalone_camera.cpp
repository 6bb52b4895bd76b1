#include "api/standalone_camera.h"

#include <fmt/core.h>

#include "core/error.h"
#include "scene/scene_desc.h"

namespace lensrt {

StandaloneCamera makeStandaloneCamera(const CameraOptions& options, int width, int height,
                                      const Transform& worldFromCamera, Warnings& warnings) {
  if (width < 2 || height < 2 || width > 65536 || height > 65536)
    throw UsageError("--res", fmt::format("expected 2x2 to 65536x65536 pixels, got {}x{}", width, height));
  const std::optional<double> focus = parseFocus(options.focus);
  if (!focus)
    throw UsageError("--focus",
                     "expected a distance in metres or inf: 'auto' measures a scene, and there is none");
  FilmGeometry film;
  film.width = width;
  film.height = height;
  CameraDesc desc;
  desc.worldFromCamera = worldFromCamera;
  return {makeCamera(options, desc, film, {}, warnings), *focus};
}

}  // namespace lensrt
