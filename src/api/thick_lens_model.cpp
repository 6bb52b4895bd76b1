// The lens's paraxial model: its cardinal points and pupils.
#include <fmt/core.h>

#include "api/camera_models.h"
#include "camera/thick_lens_camera.h"
#include "optics/chromatic.h"

namespace lensrt {

CameraModelInfo thickLensModel() {
  return {CameraModel::Thick, "thick", "the lens's paraxial model: its cardinal points and pupils", true,
          [](const CameraBuild& b) -> std::unique_ptr<Camera> {
            if (b.keyedFNumber && *b.keyedFNumber < b.paraxial->fNumber * (1 - 1e-9))
              b.warnings.warn(
                  fmt::format("{}: f/{:g} is wider than the lens allows; the thick lens opens to it anyway",
                              b.lensName, *b.keyedFNumber));
            ThickLensParams p = thickLensFromParaxial(*b.paraxial, b.fNumber, b.focusMetres);
            p.aperture = b.aperture;
            p.lensName = b.lensName;
            p.movements = b.movements;
            p.diffraction = b.spec.diffraction;
            if (b.spec.dispersion && hasDispersion(*b.lens)) p.dispersion.emplace(*b.lens);
            return std::make_unique<ThickLensCamera>(b.worldFromCamera, b.film, p, b.exposure);
          }};
}

}  // namespace lensrt
