// Motion blur from poses: a scene posed at evenly spaced moments over the
// time it is recorded becomes one SceneDesc whose moving instances carry
// their placement (and deformed mesh) at each moment (MeshInstance::motion),
// which the Embree scene interpolates linearly between steps.
#pragma once

#include <map>
#include <vector>

#include "core/transform.h"
#include "core/warnings.h"
#include "scene/scene_desc.h"

namespace lensrt {

// The most degrees a node may turn between two time steps: linear steps
// make a spinning object's blur a polygon of chords, and at 10 degrees
// they stay within 0.4% of its radius of the true arc.
inline constexpr double kMaxDegreesPerMotionStep = 10.0;
inline constexpr int kMaxMotionSteps = 129;  // Embree's limit on time steps

// How many evenly spaced time steps a span needs, from every node's world
// transform at evenly spaced probe moments over it (the first and the last
// at the span's ends): enough that no node turns more than
// kMaxDegreesPerMotionStep per step, and at least one step per probe
// interval when a node's path between the ends is not a straight line at
// constant speed; 2 for straight, steady motion.
int motionStepCount(const std::vector<std::map<int, Transform>>& probeWorlds);

// Gives `still` (the scene at the span's start) the motion of `poses` (the
// same file posed at the following steps, evenly spaced to the span's end).
// An instance moves when a pose places it elsewhere or deforms its mesh;
// deformed meshes are appended to still.meshes. When the poses differ in
// what they contain (instances, vertex or triangle counts), the scene stays
// still with a warning.
void addMotion(SceneDesc& still, const std::vector<SceneDesc>& poses, Warnings& warnings);

}  // namespace lensrt
