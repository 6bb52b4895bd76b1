// glTF metallic-roughness materials and their textures.
#pragma once

#include <tiny_gltf.h>

#include <string>

#include "scene/gltf_context.h"
#include "scene/scene_desc.h"

namespace lensrt::gltf {

// Image loader for tinygltf that never decodes (and so never fails): it keeps
// the encoded bytes of external and data-URI images (as_is) and leaves
// bufferView images for later, because tinygltf hands those over without
// checking the view against its buffer.
bool deferImageDecoding(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn,
                        int reqWidth, int reqHeight, const unsigned char* bytes, int size, void* user);

// Appends every glTF material to desc.materials (same indices) and the textures
// they use to desc.textures (decoded to linear float; baseColor and emissive
// from sRGB). A texture that is missing or cannot be decoded is dropped with a
// warning, leaving the factor alone.
void loadMaterials(const Context& ctx, SceneDesc& desc);

}  // namespace lensrt::gltf
