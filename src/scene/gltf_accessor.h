// Bounds-checked reading of glTF accessors (any component type, normalized
// integers, byteStride, sparse substitution) into plain arrays.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/gltf_context.h"

namespace lensrt::gltf {

// Reads accessor `index` as `components` floats per element (row-major, count *
// components values). Normalized integers map to [0,1] / [-1,1] as the glTF
// spec says; other integers convert by value. Throws InputError naming `what`
// when the accessor is missing, has the wrong type, or reads outside its buffer.
std::vector<float> readFloats(const Context& ctx, int index, int components, const char* what);

// Reads a SCALAR accessor of unsigned integers (vertex indices).
std::vector<std::uint32_t> readIndices(const Context& ctx, int index, const char* what);

// Element count of accessor `index` (checked).
std::size_t accessorCount(const Context& ctx, int index, const char* what);

}  // namespace lensrt::gltf
