// A scene without a camera is framed for the chosen camera's own field of
// view: its bounding box projects inside the frame and fills most of the
// shorter side. The fields are closed forms (tan = half the sensor side over
// the focal length at infinity focus), not the framing code's.
#include "api/camera_framing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "api/lens_loading.h"
#include "core/constants.h"
#include "optics/paraxial.h"
#include "scene/camera_selection.h"

namespace lensrt {
namespace {

// A standing figure's box (CesiumMan's proportions: 1.5 m tall), off the origin.
const Bounds3f kFigure{Vec3f(-0.3f, 0.0f, -0.2f), Vec3f(0.4f, 1.5f, 0.25f)};

struct Fill {
  double shorter = 0;  // the box's extent over the frame's, shorter side
  bool inside = true;  // every corner inside the frame
};

// Projects the box's corners through a rectilinear field whose half-sides
// have tangents tanX, tanY (camera looks down -Z).
Fill projectedFill(const CameraDesc& cam, double tanX, double tanY) {
  const Transform cameraFromWorld = cam.worldFromCamera.inverse();
  double lo = 1e9, hi = -1e9;
  Fill fill;
  for (int i = 0; i < 8; ++i) {
    const Vec3d corner((i & 1 ? kFigure.hi : kFigure.lo).x, (i & 2 ? kFigure.hi : kFigure.lo).y,
                       (i & 4 ? kFigure.hi : kFigure.lo).z);
    const Vec3d c = cameraFromWorld.point(corner);
    const double x = c.x / -c.z / tanX, y = c.y / -c.z / tanY;  // -1..1 across the frame
    fill.inside = fill.inside && c.z < 0 && std::abs(x) <= 1 && std::abs(y) <= 1;
    const double s = tanY <= tanX ? y : x;
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  fill.shorter = (hi - lo) / 2;
  return fill;
}

CameraSpec spec(CameraModel model, double focusMetres) {
  CameraSpec c;
  c.model = model;
  c.sensorMm = {36, 24};
  c.focusMetres = focusMetres;
  return c;
}

TEST(CameraFraming, ThinLens50mmFitsTheFigureInItsField) {
  CameraSpec c = spec(CameraModel::Thin, kInfinity);
  c.focalLengthMm = 50;
  const float aspect = 1.5f;  // 36x24
  const CameraDesc cam = frameBounds(kFigure, aspect, cameraFramingField(c)(aspect));
  const Fill fill = projectedFill(cam, 18.0 / 50, 12.0 / 50);
  EXPECT_TRUE(fill.inside);
  EXPECT_GT(fill.shorter, 0.8);
  EXPECT_LE(fill.shorter, 1.0);
  RecordProperty("fill", std::to_string(fill.shorter));
}

TEST(CameraFraming, Dgauss50mmFullLensAndPortraitFrame) {
  const double efl =
      computeParaxial(loadUserLens("dgauss-50mm", CameraSpec::defaultLensDir()).prescription).efl;
  for (const CameraModel model : {CameraModel::Pinhole, CameraModel::Thick, CameraModel::Lens}) {
    CameraSpec c = spec(model, kInfinity);
    c.lens = "dgauss-50mm";
    for (const float aspect : {1.5f, 2.0f / 3.0f}) {  // 36x24, and 16x24 cropped for a portrait frame
      const double w = aspect > 1 ? 36.0 : 16.0, h = 24.0;
      const CameraDesc cam = frameBounds(kFigure, aspect, cameraFramingField(c)(aspect));
      // The full lens's real field differs from the paraxial by its
      // distortion (< 1% here): allow 2% on the closed form.
      const double slack = model == CameraModel::Lens ? 1.02 : 1.0;
      const Fill fill = projectedFill(cam, slack * 0.5 * w / efl, slack * 0.5 * h / efl);
      EXPECT_TRUE(fill.inside) << int(model) << " aspect " << aspect;
      // The tall figure fills the landscape frame's height; in portrait the
      // shorter side is its width (the sphere fits it: inside is the check).
      if (aspect > 1) EXPECT_GT(fill.shorter, 0.8) << int(model);
      std::printf("model %d aspect %.3f fill %.3f\n", int(model), aspect, fill.shorter);
    }
  }
}

}  // namespace
}  // namespace lensrt
