// glTF 2.0 (.gltf, .glb, embedded data URIs) into the neutral SceneDesc.
//
// What is loaded: the node hierarchy of one scene (TRS or matrix), triangle
// primitives (TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN, indexed or not, any
// accessor component type, normalized integers, sparse accessors, byteStride),
// repeated meshes as instances, EXT_mesh_gpu_instancing, perspective cameras
// (orthographic ones are kept, marked and warned about), metallic-roughness
// materials with baseColor / metallicRoughness / normal / emissive textures,
// KHR_materials_emissive_strength, KHR_lights_punctual (units: see
// gltf_lights.cpp), node animations, morph targets and skins at a moment
// (gltf_animation.h, gltf_mesh.h). Everything else the file uses is named in
// one warning each; a required extension we do not implement is an error.
#pragma once

#include <filesystem>
#include <memory>

#include "core/warnings.h"
#include "scene/animation_time.h"
#include "scene/scene_desc.h"
#include "scene/scene_file_access.h"

namespace lensrt {

// A glTF file parsed once and posed at any number of moments (`--frames`).
// The constructor reads and checks the file and picks its scene; load()
// poses it. Throws as loadGltf does.
class GltfLoader {
 public:
  GltfLoader(const std::filesystem::path& file, int sceneIndex, Warnings& warnings,
             const SceneReadLimits& limits = {});
  ~GltfLoader();
  GltfLoader(const GltfLoader&) = delete;
  GltfLoader& operator=(const GltfLoader&) = delete;

  // The scene posed at `time`, with its materials and textures: read from
  // the file, or when `previous` is given (a scene this loader made before)
  // taken from it, which saves decoding the textures again.
  SceneDesc load(const AnimationTime& time, SceneDesc* previous = nullptr);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// sceneIndex: -1 for the file's default scene (its "scene" property, else scene
// 0), otherwise a 0-based index into the file's scenes. Throws InputError(file,
// one-line message) for unreadable or broken input, and when the scene has no
// non-degenerate triangle to render; SelectionError (an InputError) when the
// file has no scene `sceneIndex`. `limits` says what the file may make the
// loader read and hold: by default only files in its folder
// (scene_file_access.h); a URI refused, a data: URI or a texture over its
// limit is an InputError naming it. `time`: the moment the animations
// (scene/gltf_animation.h) pose the nodes, cameras and lights at.
SceneDesc loadGltf(const std::filesystem::path& file, int sceneIndex, Warnings& warnings,
                   const SceneReadLimits& limits = {}, const AnimationTime& time = {});

}  // namespace lensrt
