// When a scene is posed: the moment the shutter opens and which of the
// file's animations play (scene/gltf_animation.h evaluates them).
#pragma once

#include <string>

namespace lensrt {

struct AnimationTime {
  double seconds = 0.0;
  std::string animation;  // a name or a 0-based index; empty: every animation plays

  bool operator==(const AnimationTime&) const = default;
};

}  // namespace lensrt
