// Affine transforms as 4x4 matrices in double precision (glTF node matrices
// compose deep hierarchies; double keeps them exact enough for float geometry).
// Names read right to left: worldFromCamera maps camera space to world space.
#pragma once

#include <array>

#include "core/bounds.h"
#include "core/ray.h"
#include "core/vec.h"

namespace lensrt {

class Transform {
 public:
  using Matrix = std::array<std::array<double, 4>, 4>;  // m[row][col], column vectors

  Transform();  // identity
  explicit Transform(const Matrix& m);

  static Transform translate(const Vec3d& t);
  static Transform scale(const Vec3d& s);
  // Unit quaternion (x, y, z, w) as glTF stores rotations.
  static Transform rotateQuaternion(double x, double y, double z, double w);
  // Column-major 16 values, as glTF's node.matrix.
  static Transform fromColumnMajor(const double* values16);
  // Camera looking from eye toward target; camera space looks down -Z with +Y up (glTF).
  static Transform lookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up);

  Transform operator*(const Transform& b) const;
  Transform inverse() const;  // throws std::domain_error when singular
  bool invertible() const { return !(inv_ == Matrix{}); }
  const Matrix& matrix() const { return m_; }
  bool operator==(const Transform&) const = default;

  Vec3d point(const Vec3d& p) const;
  Vec3d vector(const Vec3d& v) const;
  // Normals transform by the inverse transpose; the caller renormalises.
  Vec3d normal(const Vec3d& n) const;
  Vec3f point(const Vec3f& p) const { return Vec3f(point(Vec3d(p))); }
  Vec3f vector(const Vec3f& v) const { return Vec3f(vector(Vec3d(v))); }
  Vec3f normal(const Vec3f& n) const { return Vec3f(normal(Vec3d(n))); }
  Ray operator()(const Ray& r) const {
    return {point(r.origin), vector(r.direction), r.tMin, r.tMax, r.time};
  }
  Bounds3f operator()(const Bounds3f& b) const;
  // Determinant of the upper 3x3: negative when the transform mirrors (flips winding).
  double determinant3x3() const;

 private:
  Matrix m_;
  Matrix inv_;
};

}  // namespace lensrt
