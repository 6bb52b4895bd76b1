#include "scene/camera_selection.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "core/error.h"
#include "scene/selection_error.h"

namespace lensrt {
namespace {

constexpr double kElevationDegrees = 15.0;

std::string available(const SceneDesc& desc) {
  if (desc.cameras.empty()) return "the scene has no cameras";
  std::string s = "cameras:";
  // Appended piece by piece: GCC 12 warns falsely about "..." + std::string (bug 105329).
  for (const CameraDesc& c : desc.cameras) {
    s.append(" ").append(std::to_string(c.node));
    if (!c.name.empty()) s.append(" '").append(c.name).append("'");
    s.append(",");
  }
  s.pop_back();
  return s;
}

}  // namespace

CameraDesc frameBounds(const Bounds3f& bounds, float aspect, const FramingField& field) {
  Vec3d centre{0, 0, 0};
  double radius = 1;
  if (!bounds.empty()) {
    centre = Vec3d(bounds.center());
    radius = 0.5 * length(Vec3d(bounds.diagonal()));
    if (!(radius > 0)) radius = 1;
  }
  const double a = aspect > 0 && std::isfinite(aspect) ? aspect : 1.0;
  double yfov = kDefaultViewYfovDegrees * kPi / 180.0;
  const double halfV = yfov / 2;
  double distance = radius / std::sin(std::min(halfV, std::atan(a * std::tan(halfV))));
  if (field) {
    // The field narrows as the focus comes closer, and the focus follows the
    // distance: a few rounds settle it (focused on the sphere's near side,
    // the closest the scene's surfaces can be: the narrowest field).
    double focusMetres = kInfinity;
    for (int round = 0; round < 4; ++round) {
      const double h = field(focusMetres);
      if (!(h > 0 && h < kPi / 2)) break;
      // The vertical field: the shorter side's, or the longer's at this aspect.
      yfov = a >= 1 ? 2 * h : 2 * std::atan(std::tan(h) / a);
      distance = radius / std::sin(h);
      focusMetres = distance - radius;
    }
  }
  const double elevation = kElevationDegrees * kPi / 180.0;
  const Vec3d eye = centre + Vec3d(0, std::sin(elevation), std::cos(elevation)) * distance;
  CameraDesc cam;
  cam.name = "default view";
  cam.worldFromCamera = Transform::lookAt(eye, centre, {0, 1, 0});
  cam.yfov = static_cast<float>(yfov);
  cam.aspectRatio = static_cast<float>(a);
  cam.znear = static_cast<float>(0.5 * (distance - radius));
  return cam;
}

CameraDesc selectCamera(const SceneDesc& desc, const std::string& selector, float aspect,
                        const FramingField& field) {
  if (selector.empty())
    return desc.cameras.empty() ? frameBounds(desc.worldBounds(), aspect, field) : desc.cameras[0];
  const bool digits =
      std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); });
  if (digits) {
    const auto it = std::find_if(desc.cameras.begin(), desc.cameras.end(), [&](const CameraDesc& c) {
      return selector.size() < 10 && c.node == std::stoi(selector);
    });
    if (it != desc.cameras.end()) return *it;
    throw SelectionError(desc.sourceFile,
                         "node " + selector + " is not a camera node (" + available(desc) + ")");
  }
  for (const CameraDesc& c : desc.cameras)
    if (c.name == selector) return c;
  for (const CameraDesc& c : desc.cameras)
    if (c.cameraName == selector) return c;
  throw SelectionError(desc.sourceFile, "no camera named '" + selector + "' (" + available(desc) + ")");
}

}  // namespace lensrt
