// glTF mesh primitives to indexed triangle lists.
#pragma once

#include <cstddef>
#include <vector>

#include "core/transform.h"
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
// skipped with a warning. Throws InputError for broken data. `morphWeights`:
// the weights of the primitives' morph targets (POSITION, NORMAL and TANGENT
// deltas added in proportion), empty or all 0 for the base mesh.
// `joints`: for a skinned mesh, each joint's matrix (its world transform times
// its inverse bind matrix): vertices are blended by JOINTS_n / WEIGHTS_n into
// world space (glTF 2.0 3.7.3); null for a mesh placed by its node.
std::vector<int> convertMesh(const Context& ctx, int index, std::vector<Mesh>& meshes, MeshStats& stats,
                             const std::vector<double>& morphWeights = {},
                             const std::vector<Transform::Matrix>* joints = nullptr);

// The morph target weights of a node showing mesh `mesh`: its own, else the
// mesh's default ones, else none; a count that does not match the targets
// is an InputError.
std::vector<double> morphWeights(const Context& ctx, const tinygltf::Node& node, int mesh);

}  // namespace lensrt::gltf
