// When a scene is posed: the moment the shutter opens and which of the
// file's animations play (scene/gltf_animation.h evaluates them).
#pragma once

#include <string>

namespace lensrt {

struct AnimationTime {
  double seconds = 0.0;
  std::string animation;  // a name or a 0-based index; empty: every animation plays
  // How long the scene is recorded from `seconds` on (the shutter, plus a
  // rolling shutter's readout): over it moving meshes are sampled in time
  // steps for motion blur. 0: an instant.
  double spanSeconds = 0.0;

  bool operator==(const AnimationTime&) const = default;
};

}  // namespace lensrt
