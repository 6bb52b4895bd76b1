// One glTF file posed frame after frame (`lensrt render --frames`). The file
// is parsed and its textures decoded once; each frame poses the nodes, skins
// and morphs (and their motion over the shutter) and builds its BVH afresh
// from them. A refit would keep the first frame's tree, whose traversal
// order could then break a tie between hits differently, and a frame would
// no longer be bit for bit a single render of it.
#pragma once

#include <memory>

#include "api/scene.h"
#include "core/warnings.h"

namespace lensrt {

class GltfLoader;

class SceneSequence {
 public:
  // Reads and checks the file: throws as Scene's constructor does.
  // `warnings` must outlive the sequence.
  SceneSequence(const SceneLoadOptions& options, Warnings& warnings);
  ~SceneSequence();
  SceneSequence(const SceneSequence&) = delete;
  SceneSequence& operator=(const SceneSequence&) = delete;

  // The scene when the shutter opens at `seconds` (the options' animation
  // and span kept). The previous frame's scene hands its materials,
  // textures and file digests over (a copy of them while something else
  // still holds it). Not thread-safe: one call at a time.
  std::shared_ptr<const Scene> at(double seconds);
  // The same, recorded over `spanSeconds` instead of the options' span (a
  // render with another shutter).
  std::shared_ptr<const Scene> at(double seconds, double spanSeconds);

 private:
  SceneLoadOptions options_;
  std::unique_ptr<GltfLoader> loader_;
  std::shared_ptr<Scene> last_;
};

}  // namespace lensrt
