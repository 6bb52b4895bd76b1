#include "api/scene.h"

#include <chrono>

#include "api/scene_digest.h"
#include "core/error.h"
#include "scene/gltf_loader.h"
#include "scene/selection_error.h"

namespace lensrt {
namespace {

// Asking for a scene the file does not have is a wrong flag value (exit 2),
// not a broken file.
SceneDesc loadScene(const SceneLoadOptions& options, Warnings& warnings) {
  try {
    return loadGltf(options.file, options.sceneIndex, warnings, options.limits, options.time);
  } catch (const SelectionError& e) {
    throw UsageError("--scene-index", e.file() + ": " + e.message());
  }
}

}  // namespace

Scene::Scene(const SceneLoadOptions& options, Warnings& warnings)
    : options_(options), geometry_(loadScene(options, warnings)), materials_(geometry_.desc()) {
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

Scene::Scene(const SceneLoadOptions& options, SceneDesc posed, double poseSeconds)
    : options_(options), geometry_(std::move(posed)), materials_(geometry_.desc()) {
  seconds_ = poseSeconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

std::string Scene::digest(const std::string& environmentMap) const {
  const std::lock_guard lock(digestMutex_);
  auto found = digests_.find(environmentMap);
  if (found == digests_.end())
    found = digests_
                .emplace(environmentMap,
                         sceneDigest(options_.file, environmentMap, options_.limits.allowExternalFiles))
                .first;
  return found->second;
}

}  // namespace lensrt
