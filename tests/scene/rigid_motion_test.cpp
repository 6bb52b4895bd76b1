// The quaternion decomposition handed to Embree (scene/rigid_motion.h)
// against the transform it stands for: T R S rebuilt from its fields by the
// formula Embree documents gives back the matrix, for rotations, scales,
// shears and mirrors; a singular one has none.
#include "scene/rigid_motion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lensrt {
namespace {

// T R S from the fields, as rtcore_quaternion.h defines them.
Transform::Matrix rebuilt(const RTCQuaternionDecomposition& d) {
  const double w = d.quaternion_r, x = d.quaternion_i, y = d.quaternion_j, z = d.quaternion_k;
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  const Transform r = Transform::rotateQuaternion(x / n, y / n, z / n, w / n);
  Transform::Matrix s{};
  s[0] = {d.scale_x, d.skew_xy, d.skew_xz, d.shift_x};
  s[1] = {0, d.scale_y, d.skew_yz, d.shift_y};
  s[2] = {0, 0, d.scale_z, d.shift_z};
  s[3] = {0, 0, 0, 1};
  return (Transform::translate({d.translation_x, d.translation_y, d.translation_z}) * r * Transform(s))
      .matrix();
}

void expectSame(const Transform::Matrix& a, const Transform::Matrix& b) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[r][c], b[r][c], 1e-5) << r << "," << c;
}

TEST(RigidMotion, TheDecompositionRebuildsTheTransform) {
  const Transform turn = Transform::rotateQuaternion(0.2, -0.4, 0.3, std::sqrt(1 - 0.04 - 0.16 - 0.09));
  Transform::Matrix shear{};
  shear[0] = {1, 0.3, -0.2, 0};
  shear[1] = {0.1, 1, 0.4, 0};
  shear[2] = {0, -0.25, 1, 0};
  shear[3] = {0, 0, 0, 1};
  for (const Transform& xf :
       {Transform(), turn, Transform::translate({1, -2, 3}) * turn * Transform::scale({2, 0.5, 3}),
        turn * Transform(shear), Transform::translate({0, 1, 0}) * turn * Transform::scale({1, -1, 1}),
        Transform::scale({-2, -2, -2}), Transform::rotateQuaternion(0, 0, 1, 0)}) {
    const auto d = quaternionDecomposition(xf);
    ASSERT_TRUE(d);
    expectSame(rebuilt(*d), xf.matrix());
  }
  EXPECT_FALSE(quaternionDecomposition(Transform::scale({1, 0, 1})));
}

// Consecutive quaternions on the same side: 170 then 190 degrees about z is
// a 20 degree turn, not 340 the other way.
TEST(RigidMotion, StepsTurnTheShortWay) {
  const auto about = [](double degrees) {
    const double h = degrees * M_PI / 360;
    return Transform::rotateQuaternion(0, 0, std::sin(h), std::cos(h));
  };
  const auto steps = rigidMotionSteps({about(170), about(190)});
  ASSERT_TRUE(steps);
  const RTCQuaternionDecomposition &a = (*steps)[0], &b = (*steps)[1];
  EXPECT_GT(a.quaternion_r * b.quaternion_r + a.quaternion_k * b.quaternion_k, 0.98);
  expectSame(rebuilt(b), about(190).matrix());
  EXPECT_FALSE(rigidMotionSteps({about(0), Transform::scale({0, 0, 0})}));
}

}  // namespace
}  // namespace lensrt
