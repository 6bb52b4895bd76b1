// glTF 2.0 node animation at one moment: the translation, rotation and scale
// channels of the animations that play, each sampler evaluated at the time
// (LINEAR, with spherical interpolation for rotations; STEP; CUBICSPLINE with
// the specification's Hermite tangents), clamped to its first and last
// keyframes. Channels animate translation, rotation, scale and morph-target
// weights; skins are not posed yet.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/animation_time.h"
#include "scene/gltf_context.h"

namespace lensrt::gltf {

// What the animations set on a node, replacing its own values.
struct AnimatedTrs {
  std::optional<std::array<double, 3>> translation, scale;
  std::optional<std::array<double, 4>> rotation;  // x, y, z, w (unit)
  std::optional<std::vector<double>> weights;     // morph target weights of its mesh
};

// Node index -> its animated values. Throws UsageError("--animation") for an
// animation the file does not have; a channel whose data is broken (times
// that do not increase or are not finite, counts that do not match the
// interpolation) is skipped with one warning naming it. With several
// animations playing, a notice says so; where two set the same value, the
// later one in the file wins.
std::map<int, AnimatedTrs> animatedNodes(const Context& ctx, const AnimationTime& time);

// The sampler formulas on keyframe values (tested against the specification's
// formulas): LINEAR between a and b at u in [0, 1]; CUBICSPLINE's Hermite
// curve through values v0, v1 with out-tangent b0 and in-tangent a1, over a
// keyframe interval of `dt` seconds.
std::array<double, 4> slerp(const std::array<double, 4>& a, const std::array<double, 4>& b, double u);
double hermite(double v0, double b0, double a1, double v1, double dt, double u);

}  // namespace lensrt::gltf
