// Which camera renders: --camera-node NAME|INDEX, the file's first camera, or
// a default view that frames the scene.
#pragma once

#include <functional>
#include <string>

#include "core/bounds.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The chosen camera's field: the half-angle (radians) from the axis to the
// middle of the frame's SHORTER edge, for a focus distance (metres; a lens
// takes in less when focused closer). Empty: a 40-degree vertical field.
using FramingField = std::function<double(double focusMetres)>;

// The default view when a scene has no camera (or none is wanted): it looks
// at the centre of the bounding box along -Z from the +Z side, raised 15
// degrees above the horizontal (+Y up), from the distance at which the
// bounding sphere just fits the frame's shorter field of view for `aspect`
// (width / height): `field`'s, focused on the sphere's near side, else
// yfov 40 degrees. yfov is the vertical field (rectilinear). znear is half
// the distance to the sphere. An empty box frames the unit sphere at the
// origin.
inline constexpr double kDefaultViewYfovDegrees = 40.0;
CameraDesc frameBounds(const Bounds3f& bounds, float aspect, const FramingField& field = {});

// selector "" : the first camera the default scene's traversal found, else
//               frameBounds(desc.worldBounds(), aspect, field) (named "default view").
// selector of digits only: the glTF node index of a camera node.
// other text: a camera node's name, else a glTF camera object's name.
// Throws SelectionError(desc.sourceFile, ...) listing the available cameras
// when nothing matches.
CameraDesc selectCamera(const SceneDesc& desc, const std::string& selector, float aspect,
                        const FramingField& field = {});

}  // namespace lensrt
