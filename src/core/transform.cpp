#include "core/transform.h"

#include <cmath>
#include <stdexcept>

namespace lensrt {
namespace {

using Matrix = Transform::Matrix;

Matrix identity() {
  Matrix m{};
  for (int i = 0; i < 4; ++i) m[i][i] = 1.0;
  return m;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

// Gauss-Jordan with partial pivoting; throws for singular matrices.
Matrix invert(const Matrix& in) {
  Matrix a = in;
  Matrix inv = identity();
  for (int c = 0; c < 4; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
    if (std::abs(a[pivot][c]) < 1e-300 || !std::isfinite(a[pivot][c]))
      throw std::domain_error("singular transform");
    std::swap(a[c], a[pivot]);
    std::swap(inv[c], inv[pivot]);
    const double s = 1.0 / a[c][c];
    for (int j = 0; j < 4; ++j) {
      a[c][j] *= s;
      inv[c][j] *= s;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == c) continue;
      const double f = a[r][c];
      for (int j = 0; j < 4; ++j) {
        a[r][j] -= f * a[c][j];
        inv[r][j] -= f * inv[c][j];
      }
    }
  }
  return inv;
}

}  // namespace

Transform::Transform() : m_(identity()), inv_(identity()) {}

Transform::Transform(const Matrix& m) : m_(m), inv_{} {
  // Singular matrices (a zero scale) are legal in glTF; keep a zero inverse so
  // that only inverse() reports the problem.
  try {
    inv_ = invert(m);
  } catch (const std::domain_error&) {
    inv_ = Matrix{};
  }
}

Transform Transform::translate(const Vec3d& t) {
  Matrix m = identity();
  m[0][3] = t.x;
  m[1][3] = t.y;
  m[2][3] = t.z;
  return Transform(m);
}

Transform Transform::scale(const Vec3d& s) {
  Matrix m = identity();
  m[0][0] = s.x;
  m[1][1] = s.y;
  m[2][2] = s.z;
  return Transform(m);
}

Transform Transform::rotateQuaternion(double x, double y, double z, double w) {
  const double n = std::sqrt(x * x + y * y + z * z + w * w);
  if (n > 0) {
    x /= n;
    y /= n;
    z /= n;
    w /= n;
  }
  Matrix m = identity();
  m[0][0] = 1 - 2 * (y * y + z * z);
  m[0][1] = 2 * (x * y - z * w);
  m[0][2] = 2 * (x * z + y * w);
  m[1][0] = 2 * (x * y + z * w);
  m[1][1] = 1 - 2 * (x * x + z * z);
  m[1][2] = 2 * (y * z - x * w);
  m[2][0] = 2 * (x * z - y * w);
  m[2][1] = 2 * (y * z + x * w);
  m[2][2] = 1 - 2 * (x * x + y * y);
  return Transform(m);
}

Transform Transform::fromColumnMajor(const double* v) {
  Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[r][c] = v[c * 4 + r];
  return Transform(m);
}

Transform Transform::lookAt(const Vec3d& eye, const Vec3d& target, const Vec3d& up) {
  const Vec3d back = normalize(eye - target);  // camera +Z points away from the view
  Vec3d right = cross(up, back);
  if (length(right) < 1e-12) right = cross(Vec3d(1, 0, 0), back);
  if (length(right) < 1e-12) right = cross(Vec3d(0, 0, 1), back);
  right = normalize(right);
  const Vec3d trueUp = cross(back, right);
  Matrix m = identity();
  for (int r = 0; r < 3; ++r) {
    m[r][0] = right[r];
    m[r][1] = trueUp[r];
    m[r][2] = back[r];
    m[r][3] = eye[r];
  }
  return Transform(m);
}

Transform Transform::operator*(const Transform& b) const {
  Transform t;
  t.m_ = multiply(m_, b.m_);
  t.inv_ = multiply(b.inv_, inv_);
  return t;
}

Transform Transform::inverse() const {
  if (inv_ == Matrix{}) throw std::domain_error("singular transform");
  Transform t;
  t.m_ = inv_;
  t.inv_ = m_;
  return t;
}

Vec3d Transform::point(const Vec3d& p) const {
  Vec3d r;
  for (int i = 0; i < 3; ++i) r[i] = m_[i][0] * p.x + m_[i][1] * p.y + m_[i][2] * p.z + m_[i][3];
  const double w = m_[3][0] * p.x + m_[3][1] * p.y + m_[3][2] * p.z + m_[3][3];
  return w == 1.0 ? r : r / w;
}

Vec3d Transform::vector(const Vec3d& v) const {
  Vec3d r;
  for (int i = 0; i < 3; ++i) r[i] = m_[i][0] * v.x + m_[i][1] * v.y + m_[i][2] * v.z;
  return r;
}

Vec3d Transform::normal(const Vec3d& n) const {
  Vec3d r;
  for (int i = 0; i < 3; ++i) r[i] = inv_[0][i] * n.x + inv_[1][i] * n.y + inv_[2][i] * n.z;
  return r;
}

Bounds3f Transform::operator()(const Bounds3f& b) const {
  Bounds3f out;
  if (b.empty()) return out;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3f p{(corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                  (corner & 4) ? b.hi.z : b.lo.z};
    out.extend(point(p));
  }
  return out;
}

double Transform::determinant3x3() const {
  return m_[0][0] * (m_[1][1] * m_[2][2] - m_[1][2] * m_[2][1]) -
         m_[0][1] * (m_[1][0] * m_[2][2] - m_[1][2] * m_[2][0]) +
         m_[0][2] * (m_[1][0] * m_[2][1] - m_[1][1] * m_[2][0]);
}

}  // namespace lensrt
