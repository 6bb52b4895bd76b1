// State shared by the pieces of the glTF loader (internal to src/scene).
#pragma once

#include <tiny_gltf.h>

#include <string>
#include <string_view>

#include "core/error.h"
#include "core/warnings.h"
#include "scene/scene_file_access.h"

namespace lensrt::gltf {

struct Context {
  const tinygltf::Model& model;
  std::string file;  // for messages
  Warnings& warnings;
  const SceneReadLimits& limits;

  [[noreturn]] void fail(const std::string& message) const { throw InputError(file, message); }

  void warnUnsupportedExtension(const std::string& name) const {
    warnings.warn("extension " + name + " is not supported and is ignored");
  }
};

// The extensions the loader implements (KHR_mesh_quantization needs nothing
// beyond the accessor reader's integer formats; KHR_xmp and KHR_xmp_json_ld are
// metadata that cannot change the picture; EXT_texture_webp's images need the
// OpenImageIO plugin, an error when it is missing and no fallback image is given).
inline bool isSupportedExtension(std::string_view name) {
  return name == "KHR_lights_punctual" || name == "KHR_materials_emissive_strength" ||
         name == "EXT_mesh_gpu_instancing" || name == "KHR_mesh_quantization" ||
         name == "KHR_texture_transform" || name == "KHR_xmp" || name == "KHR_xmp_json_ld" ||
         name == "KHR_materials_ior" || name == "KHR_materials_specular" ||
         name == "KHR_materials_transmission" || name == "KHR_materials_volume" ||
         name == "KHR_materials_clearcoat" || name == "KHR_materials_sheen" ||
         name == "KHR_materials_dispersion" || name == "EXT_texture_webp";
}

}  // namespace lensrt::gltf
