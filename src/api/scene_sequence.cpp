#include "api/scene_sequence.h"

#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "core/error.h"
#include "scene/gltf_loader.h"
#include "scene/selection_error.h"

namespace lensrt {

SceneSequence::SceneSequence(const SceneLoadOptions& options, Warnings& warnings) : options_(options) {
  try {
    loader_ = std::make_unique<GltfLoader>(options.file, options.sceneIndex, warnings, options.limits);
  } catch (const SelectionError& e) {
    throw UsageError("--scene-index", e.file() + ": " + e.message());
  }
}

SceneSequence::~SceneSequence() = default;

std::shared_ptr<const Scene> SceneSequence::at(double seconds) {
  return at(seconds, options_.time.spanSeconds);
}

std::shared_ptr<const Scene> SceneSequence::at(double seconds, double spanSeconds) {
  const auto started = std::chrono::steady_clock::now();
  SceneLoadOptions options = options_;
  options.time.seconds = seconds;
  options.time.spanSeconds = spanSeconds;
  // The last frame's materials and textures: taken when nothing else holds
  // it any more, else copied (still cheaper than decoding the textures).
  std::optional<SceneDesc> previous;
  std::map<std::string, std::string> digests;
  if (last_ && last_.use_count() == 1) {
    digests = std::move(last_->digests_);
    previous = std::move(last_->geometry_).releaseDesc();
  } else if (last_) {
    const SceneDesc& held = last_->geometry().desc();
    previous.emplace();
    previous->materials = held.materials;
    previous->textures = held.textures;
    const std::lock_guard lock(last_->digestMutex_);
    digests = last_->digests_;
  }
  last_.reset();
  SceneDesc posed = loader_->load(options.time, previous ? &*previous : nullptr);
  previous.reset();
  const double poseSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  auto scene = std::make_shared<Scene>(options, std::move(posed), poseSeconds);
  scene->digests_ = std::move(digests);
  last_ = scene;
  return scene;
}

}  // namespace lensrt
