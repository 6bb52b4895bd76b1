// A 3x3 matrix in double, row-major: colour-space conversions and fits.
#pragma once

#include <array>
#include <optional>

#include "core/vec.h"

namespace lensrt {

struct Mat3d {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};  // identity

  static constexpr Mat3d diagonal(const Vec3d& d) {
    Mat3d r;
    r.m = {{{d.x, 0, 0}, {0, d.y, 0}, {0, 0, d.z}}};
    return r;
  }
  // The matrix whose columns are a, b, c.
  static constexpr Mat3d columns(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    Mat3d r;
    r.m = {{{a.x, b.x, c.x}, {a.y, b.y, c.y}, {a.z, b.z, c.z}}};
    return r;
  }
  constexpr double operator()(int row, int col) const { return m[std::size_t(row)][std::size_t(col)]; }

  constexpr Vec3d operator*(const Vec3d& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  constexpr Mat3d operator*(const Mat3d& b) const {
    Mat3d r;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        r.m[i][j] = m[i][0] * b.m[0][j] + m[i][1] * b.m[1][j] + m[i][2] * b.m[2][j];
    return r;
  }
  constexpr Mat3d transpose() const {
    Mat3d r;
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
    return r;
  }
  constexpr double determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  // None when singular.
  constexpr std::optional<Mat3d> inverse() const {
    const double det = determinant();
    if (!(det != 0)) return std::nullopt;
    Mat3d r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        // Cofactor of (j, i) over the determinant (the adjugate).
        const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        r.m[std::size_t(i)][std::size_t(j)] =
            ((*this)(r0, c0) * (*this)(r1, c1) - (*this)(r0, c1) * (*this)(r1, c0)) / det;
      }
    return r;
  }
};

}  // namespace lensrt
