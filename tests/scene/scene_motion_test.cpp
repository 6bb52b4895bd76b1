// The motion steps a span needs (scene/scene_motion.h), from node worlds at
// evenly spaced probes: straight steady motion takes 2, turning takes one
// step per 10 degrees, a curved path one per probe interval, at most 129.
#include "scene/scene_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "core/constants.h"

namespace lensrt {
namespace {

// Node 0's world at each of 9 probes over the span, from `pose(fraction)`.
template <class Pose>
std::vector<std::map<int, Transform>> probes(Pose pose) {
  std::vector<std::map<int, Transform>> worlds;
  for (int k = 0; k <= 8; ++k) worlds.push_back({{0, pose(k / 8.0)}});
  return worlds;
}

TEST(SceneMotion, StraightSteadyMotionTakesTwoSteps) {
  EXPECT_EQ(motionStepCount(probes([](double f) { return Transform::translate({3 * f, -f, 0}); })), 2);
  EXPECT_EQ(motionStepCount(probes([](double) { return Transform(); })), 2);
}

TEST(SceneMotion, TurningTakesAStepPerTenDegrees) {
  const auto turning = [](double degrees) {
    return probes([degrees](double f) {
      const double half = 0.5 * degrees * f * kPi / 180;
      return Transform::rotateQuaternion(0, 0, std::sin(half), std::cos(half));
    });
  };
  EXPECT_EQ(motionStepCount(turning(90)), 10);     // 9 steps of 10 degrees
  EXPECT_EQ(motionStepCount(turning(95)), 11);     // 10 of 9.5
  EXPECT_EQ(motionStepCount(turning(720)), 73);    // two turns, 90 degrees between probes
  EXPECT_EQ(motionStepCount(turning(1400)), 129);  // 141 by the rule, Embree's most
  // Over 180 degrees between probes aliases: 8 probes see at most 1440 degrees
  // (5000 degrees look like 760), a limit the README states.
}

TEST(SceneMotion, ACurvedPathTakesAStepPerProbeInterval) {
  // A quarter circle, not turning the node itself, and a straight path at changing speed.
  EXPECT_EQ(motionStepCount(probes([](double f) {
              const double a = 0.5 * kPi * f;
              return Transform::translate({std::cos(a), std::sin(a), 0});
            })),
            9);
  EXPECT_EQ(motionStepCount(probes([](double f) { return Transform::translate({f * f, 0, 0}); })), 9);
}

}  // namespace
}  // namespace lensrt
