// The pinhole: an ideal centre of projection. With a lens it takes the
// lens's field of view at its focus; its film records radiance unless
// --film irradiance asks for the physical film.
#include "api/camera_models.h"
#include "camera/pinhole_camera.h"
#include "camera/thick_lens_camera.h"

namespace lensrt {

CameraModelInfo pinholeModel() {
  return {CameraModel::Pinhole, "pinhole", "an ideal pinhole: no depth of field", false,
          [](const CameraBuild& b) -> std::unique_ptr<Camera> {
            // A pinhole has no plane of focus to tilt: its film only shifts.
            LensMovements shift;
            shift.shiftMm = b.movements.shiftMm;
            const double yfov = b.paraxial
                                    ? lensVerticalFov(*b.paraxial, b.focusMetres, b.film.sensorHeightMm)
                                    : b.yfovInfinity;
            if (b.spec.film == FilmQuantity::Irradiance)
              return std::make_unique<PinholeCamera>(b.worldFromCamera, b.film, yfov, b.exposure, b.fNumber,
                                                     b.lensName, shift);
            return std::make_unique<PinholeCamera>(b.worldFromCamera, b.film, yfov, b.lensName, shift);
          }};
}

}  // namespace lensrt
