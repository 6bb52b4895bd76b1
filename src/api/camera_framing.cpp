#include "api/camera_framing.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>

#include "api/camera_factory.h"
#include "api/lens_loading.h"
#include "camera/thick_lens_camera.h"
#include "core/constants.h"
#include "optics/distortion.h"
#include "optics/focus.h"
#include "optics/lens_system.h"
#include "optics/paraxial.h"

namespace lensrt {

std::function<FramingField(float aspect)> cameraFramingField(const CameraSpec& camera) {
  std::optional<LensPrescription> lens;
  if (!camera.lens.empty()) {
    try {
      UserLens user = loadUserLens(camera.lens, camera.lensDir);
      requireRealImage(user);
      if (camera.focalLengthMm)
        user.prescription =
            user.prescription.scaled(*camera.focalLengthMm / computeParaxial(user.prescription).efl);
      lens = user.prescription;
    } catch (const std::exception&) {
      return {};  // the camera's build names the lens and its problem
    }
  }
  if (!lens && !camera.focalLengthMm) return {};
  const Vec2d sensorMm = camera.sensorMm;
  const std::optional<double> fixedFocus = camera.autoFocus() ? std::nullopt : camera.focusMetres;
  // The half of the shorter side of the sensor, cropped to the film's aspect.
  const auto halfShortMm = [sensorMm](float aspect) {
    const FilmGeometry film = cameraFilm(sensorMm, std::max(1, int(std::lround(10000.0 * aspect))), 10000);
    return 0.5 * std::min(film.sensorWidthMm, film.sensorHeightMm);
  };

  if (lens && camera.model == CameraModel::Lens) {
    const auto system = std::make_shared<const LensSystem>(*lens);
    const double closestMm = closestFocusDistanceMm(*system);
    return [=](float aspect) -> FramingField {
      const double halfMm = halfShortMm(aspect);
      return [=](double focusMetres) {
        const double focusMm = std::max(1000.0 * fixedFocus.value_or(focusMetres), closestMm);
        try {
          const double filmMm = focusFilmDistance(*system, focusMm);
          return fieldForImageHeight(*system, focusMm, filmMm, halfMm).angleDeg * kPi / 180.0;
        } catch (const std::exception&) {
          return 0.0;  // not framed by this lens: the default view's field
        }
      };
    };
  }
  // The paraxial optics: the lens's, or an ideal thin lens of the focal length
  // (principal planes at the pupil). A pinhole without a lens does not focus.
  ParaxialData paraxial;
  if (lens && camera.model != CameraModel::Thin) {
    paraxial = computeParaxial(*lens);
  } else {
    paraxial.efl = camera.focalLengthMm ? *camera.focalLengthMm : computeParaxial(*lens).efl;
  }
  const bool focuses = lens || camera.model != CameraModel::Pinhole;
  const double closestM = lens ? closestFocusDistanceMm(LensSystem(*lens)) / 1000.0 : 2e-3 * paraxial.efl;
  return [=](float aspect) -> FramingField {
    const double halfMm = halfShortMm(aspect);
    return [=](double focusMetres) {
      const double focus = focuses ? std::max(fixedFocus.value_or(focusMetres), closestM) : kInfinity;
      return 0.5 * lensVerticalFov(paraxial, focus, 2.0 * halfMm);
    };
  };
}

}  // namespace lensrt
