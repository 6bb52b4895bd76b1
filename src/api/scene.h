// A glTF scene loaded once and rendered many times: the geometry and its
// BVH, the materials and the glTF's cameras. What varies per render (the
// raster, the environment, the camera, the settings) is a RenderJob's
// (api/render_job.h); Python's lensrt.Scene is this class.
#pragma once

#include <chrono>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "core/warnings.h"
#include "render/material_eval.h"
#include "scene/animation_time.h"
#include "scene/render_scene.h"
#include "scene/scene_file_access.h"

namespace lensrt {

struct SceneLoadOptions {
  std::string file;        // .gltf / .glb
  int sceneIndex = -1;     // -1: the file's default scene
  SceneReadLimits limits;  // what the scene may make lensrt read and hold
  AnimationTime time;      // the moment its animations pose it at
};

class Scene {
 public:
  // Reads the file and builds the BVH and materials. Throws InputError for a
  // bad file, UsageError ("--scene-index") for a scene the file lacks.
  Scene(const SceneLoadOptions& options, Warnings& warnings);
  // Around a scene already read and posed at options.time (SceneSequence).
  // Throws InputError for geometry Embree cannot take.
  Scene(const SceneLoadOptions& options, SceneDesc posed, double poseSeconds = 0);
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  const SceneLoadOptions& options() const { return options_; }
  const RenderScene& geometry() const { return geometry_; }
  const MaterialTable& materials() const { return materials_; }
  // Seconds it took to read the file (or, for a frame of a sequence, to pose
  // it) and to build the BVH and materials (lensrt:scene_seconds).
  double seconds() const { return seconds_; }

  // Hex SHA-256 of the scene's files and `environmentMap` (api/scene_digest.h),
  // computed once per map; safe to call from several threads.
  std::string digest(const std::string& environmentMap) const;

 private:
  // A sequence's next frame takes this one's materials, textures and digests.
  friend class SceneSequence;

  // Set first: seconds() covers the members' construction.
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  SceneLoadOptions options_;
  RenderScene geometry_;
  MaterialTable materials_;
  double seconds_ = 0;
  mutable std::mutex digestMutex_;
  mutable std::map<std::string, std::string> digests_;
};

}  // namespace lensrt
