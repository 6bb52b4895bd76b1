// KHR_lights_punctual lights in radiometric units (the rule is in gltf_lights.cpp).
#pragma once

#include <optional>

#include "core/transform.h"
#include "scene/gltf_context.h"
#include "scene/scene_desc.h"

namespace lensrt::gltf {

// Light `index` of the file placed by its node's global transform; nullopt (with
// a warning) for an unknown type or an unusable intensity.
std::optional<PunctualLight> convertLight(const Context& ctx, int index, const Transform& worldFromNode);

}  // namespace lensrt::gltf
