// Which camera renders: --camera-node NAME|INDEX, the file's first camera, or
// a default view that frames the scene.
#pragma once

#include <string>

#include "core/bounds.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The default view when a scene has no camera (or none is wanted): it looks
// at the centre of the bounding box along -Z from the +Z side, raised 15
// degrees above the horizontal (+Y up), with yfov 40 degrees, from the
// distance at which the bounding sphere just fits both the vertical and the
// horizontal field of view for `aspect` (width / height). znear is half the
// distance to the sphere. An empty box frames the unit sphere at the origin.
CameraDesc frameBounds(const Bounds3f& bounds, float aspect);

// selector "" : the first camera the default scene's traversal found, else
//               frameBounds(desc.worldBounds(), aspect) (named "default view").
// selector of digits only: the glTF node index of a camera node.
// other text: a camera node's name, else a glTF camera object's name.
// Throws SelectionError(desc.sourceFile, ...) listing the available cameras
// when nothing matches.
CameraDesc selectCamera(const SceneDesc& desc, const std::string& selector, float aspect);

}  // namespace lensrt
