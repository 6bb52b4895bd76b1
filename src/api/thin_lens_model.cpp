// The ideal thin lens: the lens's focal length and f-number (or
// --focal-length), a focal length per wavelength when the lens disperses.
#include "api/camera_models.h"
#include "camera/thin_lens_camera.h"
#include "optics/chromatic.h"

namespace lensrt {

CameraModelInfo thinLensModel() {
  return {CameraModel::Thin, "thin", "an ideal thin lens of the lens's focal length and f-number", false,
          [](const CameraBuild& b) -> std::unique_ptr<Camera> {
            ThinLensParams p;
            p.focalLengthMm = b.focalLengthMm;
            p.fNumber = b.fNumber;
            p.focusMetres = b.focusMetres;
            p.aperture = b.aperture;
            p.lensName = b.lensName;
            p.movements = b.movements;
            p.diffraction = b.spec.diffraction;
            if (b.lens && b.spec.dispersion && hasDispersion(*b.lens)) p.dispersion.emplace(*b.lens);
            return std::make_unique<ThinLensCamera>(b.worldFromCamera, b.film, p, b.exposure);
          }};
}

}  // namespace lensrt
