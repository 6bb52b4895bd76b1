// The full lens: every element traced (Kolb et al.), with its stop's shape
// (blades or a mask), coatings and stray light.
#include "api/aperture_mask_file.h"
#include "api/camera_models.h"
#include "camera/lens_camera.h"

namespace lensrt {

CameraModelInfo fullLensModel() {
  return {CameraModel::Lens, "lens", "traced through every element of the lens", true,
          [](const CameraBuild& b) -> std::unique_ptr<Camera> {
            const CameraSpec& o = b.spec;
            LensCameraParams p;
            if (!o.apertureMask.empty()) {
              p.mask = std::make_shared<const ApertureMask>(readApertureMask(o.apertureMask.string()));
            }
            p.fNumber = b.fNumber;
            p.focusMetres = b.focusMetres;
            p.aperture = b.aperture;
            p.dispersion = o.dispersion;
            p.movements = b.movements;
            p.coatings = o.coatings;
            if (b.flare.on) {
              p.flareReflections = b.flare.bounces;
              p.barrelReflectance = b.flare.barrelReflectance;
              // Stray light needs reflecting surfaces: bare glass unless --coatings says otherwise.
              if (!p.coatings) p.coatings = Coating::None;
            }
            auto camera =
                std::make_unique<LensCamera>(b.worldFromCamera, b.film, *b.lens, p, b.exposure, b.warnings);
            if (b.flareLens && camera->flare()) *b.flareLens = camera.get();
            return camera;
          }};
}

}  // namespace lensrt
