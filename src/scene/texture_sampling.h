// Texture lookup shared by the alpha-mask filter and the renderer's materials.
#pragma once

#include "core/vec.h"
#include "scene/scene_desc.h"

namespace lensrt {

// Texel centres sit at ((i + 0.5) / width, (j + 0.5) / height); uv (0,0) is the
// top-left corner of the image (glTF convention). Filtering and wrapping follow
// the texture's sampler (bilinear or nearest; repeat, mirrored repeat or clamp).
// An empty texture (failed to load) samples as opaque white, so that the
// material's factor alone decides the colour.
Vec4f sampleTexture(const Texture& texture, Vec2f uv);

}  // namespace lensrt
