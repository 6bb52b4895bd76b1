// glTF mesh primitives to indexed triangle lists.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/gltf_context.h"
#include "scene/scene_desc.h"

namespace lensrt::gltf {

// Coordinates beyond this (metres) are treated as broken input: float
// geometry that far out cannot be ray traced meaningfully.
inline constexpr double kMaxCoordinate = 1e15;

struct MeshStats {
  std::size_t degenerateTriangles = 0;  // dropped
  std::size_t triangles = 0;            // kept
};

// Converts every primitive of glTF mesh `index` (TRIANGLES, TRIANGLE_STRIP,
// TRIANGLE_FAN; indexed or not) to a Mesh appended to `meshes`; returns their
// indices. Zero-area triangles are dropped and counted; other modes are
// skipped with a warning. Throws InputError for broken data.
std::vector<int> convertMesh(const Context& ctx, int index, std::vector<Mesh>& meshes, MeshStats& stats);

}  // namespace lensrt::gltf
