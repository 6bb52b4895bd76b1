// How much of a surface is there at a point: glTF alpha (MASK cut-outs and
// BLEND coverage), shared by the scene's alpha filter and light sampling.
#pragma once

#include "scene/scene_desc.h"

namespace lensrt {

// glTF alpha at barycentric (u, v) of triangle `prim` (u weighs its second
// vertex, v its third): baseColor factor alpha * base colour texture alpha
// (through the slot's UV set and transform) * COLOR_0 alpha.
float surfaceAlpha(const SceneDesc& scene, const Mesh& mesh, const Material& material, unsigned prim, float u,
                   float v);

// The fraction of paths the surface stops there: 1 for OPAQUE, 0 or 1 for
// MASK (alpha against alphaCutoff), alpha for BLEND (stochastic transparency).
float surfaceCoverage(const SceneDesc& scene, const Mesh& mesh, const Material& material, unsigned prim,
                      float u, float v);

}  // namespace lensrt
