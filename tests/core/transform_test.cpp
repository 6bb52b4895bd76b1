#include "core/transform.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/frame.h"

namespace lensrt {
namespace {

void expectNear(const Vec3d& a, const Vec3d& b, double eps = 1e-12) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(Transform, QuaternionRotatesQuarterTurnAboutY) {
  const double s = std::sqrt(0.5);
  const Transform r = Transform::rotateQuaternion(0, s, 0, s);  // +90 deg about +Y
  expectNear(r.vector(Vec3d(1, 0, 0)), Vec3d(0, 0, -1));
  expectNear(r.vector(Vec3d(0, 0, 1)), Vec3d(1, 0, 0));
}

TEST(Transform, InverseUndoesComposition) {
  const Transform t = Transform::translate({1, 2, 3}) * Transform::rotateQuaternion(0.1, 0.2, 0.3, 0.9) *
                      Transform::scale({2, 3, 4});
  const Vec3d p{0.5, -1.5, 2.0};
  expectNear(t.inverse().point(t.point(p)), p, 1e-12);
}

TEST(Transform, NormalsStayPerpendicularUnderNonUniformScale) {
  const Transform t = Transform::scale({1, 4, 1});
  const Vec3d tangent = t.vector(Vec3d(1, -1, 0));
  const Vec3d n = t.normal(Vec3d(1, 1, 0));
  EXPECT_NEAR(dot(tangent, n), 0.0, 1e-12);
}

TEST(Transform, ColumnMajorMatchesGltfTranslation) {
  const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
  expectNear(Transform::fromColumnMajor(m).point(Vec3d(0, 0, 0)), Vec3d(5, 6, 7));
}

TEST(Transform, LookAtPointsMinusZAtTarget) {
  const Transform c = Transform::lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0});
  expectNear(c.vector(Vec3d(0, 0, -1)), Vec3d(0, 0, -1));
  const Transform side = Transform::lookAt({3, 0, 0}, {0, 0, 0}, {0, 1, 0});
  expectNear(side.vector(Vec3d(0, 0, -1)), Vec3d(-1, 0, 0));
  expectNear(side.vector(Vec3d(0, 1, 0)), Vec3d(0, 1, 0));
}

TEST(Transform, SingularInverseThrows) {
  EXPECT_THROW(Transform::scale({0, 1, 1}).inverse(), std::domain_error);
  EXPECT_FALSE(Transform::scale({0, 1, 1}).invertible());
  EXPECT_TRUE(Transform::scale({2, 1, 1}).invertible());
  // A product with a singular factor has no inverse either.
  EXPECT_FALSE((Transform::scale({2, 2, 2}) * Transform::scale({0, 1, 1})).invertible());
}

TEST(Frame, IsOrthonormalForManyNormals) {
  for (int i = 0; i < 100; ++i) {
    const float a = 0.37f * i, b = 0.11f * i - 3.0f;
    const Vec3f n = normalize(Vec3f{std::cos(a) * std::cos(b), std::sin(b), std::sin(a) * std::cos(b)});
    const Frame f = Frame::fromNormal(n);
    EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-5f);
    EXPECT_NEAR(length(f.s), 1.0f, 1e-5f);
    EXPECT_NEAR(length(f.t), 1.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace lensrt
