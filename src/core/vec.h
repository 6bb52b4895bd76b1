// Small fixed-size vectors shared by every layer. Templated so the optics can
// work in double while the renderer works in float.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

namespace lensrt {

template <class T>
struct Vec2 {
  T x{}, y{};
  constexpr Vec2() = default;
  constexpr Vec2(T x_, T y_) : x(x_), y(y_) {}
  constexpr T operator[](std::size_t i) const { return i == 0 ? x : y; }
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : y; }
  constexpr Vec2 operator+(Vec2 b) const { return {x + b.x, y + b.y}; }
  constexpr Vec2 operator-(Vec2 b) const { return {x - b.x, y - b.y}; }
  constexpr Vec2 operator*(T s) const { return {x * s, y * s}; }
  constexpr Vec2 operator/(T s) const { return {x / s, y / s}; }
  constexpr bool operator==(const Vec2&) const = default;
};

template <class T>
struct Vec3 {
  T x{}, y{}, z{};
  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <class U>
  constexpr explicit Vec3(const Vec3<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}
  constexpr T operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator+(const Vec3& b) const { return {x + b.x, y + b.y, z + b.z}; }
  constexpr Vec3 operator-(const Vec3& b) const { return {x - b.x, y - b.y, z - b.z}; }
  // Component-wise product: used for colours as well as scaling.
  constexpr Vec3 operator*(const Vec3& b) const { return {x * b.x, y * b.y, z * b.z}; }
  constexpr Vec3 operator/(const Vec3& b) const { return {x / b.x, y / b.y, z / b.z}; }
  constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(T s) const { return {x / s, y / s, z / s}; }
  constexpr Vec3& operator+=(const Vec3& b) {
    x += b.x;
    y += b.y;
    z += b.z;
    return *this;
  }
  constexpr Vec3& operator-=(const Vec3& b) {
    x -= b.x;
    y -= b.y;
    z -= b.z;
    return *this;
  }
  constexpr Vec3& operator*=(const Vec3& b) {
    x *= b.x;
    y *= b.y;
    z *= b.z;
    return *this;
  }
  constexpr Vec3& operator*=(T s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr bool operator==(const Vec3&) const = default;
};

template <class T>
struct Vec4 {
  T x{}, y{}, z{}, w{};
  constexpr Vec4() = default;
  constexpr Vec4(T x_, T y_, T z_, T w_) : x(x_), y(y_), z(z_), w(w_) {}
  constexpr Vec3<T> xyz() const { return {x, y, z}; }
  constexpr bool operator==(const Vec4&) const = default;
};

using Vec2f = Vec2<float>;
using Vec2d = Vec2<double>;
using Vec2i = Vec2<int>;
using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;
using Vec4f = Vec4<float>;
// Linear RGB radiance, irradiance or reflectance.
using Rgb = Vec3f;

template <class T>
constexpr Vec3<T> operator*(T s, const Vec3<T>& v) {
  return v * s;
}
template <class T>
constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T length(const Vec3<T>& v) {
  return std::sqrt(dot(v, v));
}
template <class T>
constexpr T lengthSquared(const Vec3<T>& v) {
  return dot(v, v);
}
template <class T>
Vec3<T> normalize(const Vec3<T>& v) {
  return v / length(v);
}
// v scaled to unit length, or nullopt when v is zero or not finite. When its
// squared length under- or overflows (a normal of 1e-25 from a fuzzed glTF),
// v is first scaled by its largest component so the result is still unit.
// (The rare rescaling is out of line so that the common case inlines: the
// renderer calls this at every hit.)
template <class T>
[[gnu::cold, gnu::noinline]] std::optional<Vec3<T>> unitVectorRescaled(const Vec3<T>& v);
template <class T>
inline std::optional<Vec3<T>> unitVector(const Vec3<T>& v) {
  const T len2 = dot(v, v);
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) [[likely]]
    return v / std::sqrt(len2);
  return unitVectorRescaled(v);
}
template <class T>
std::optional<Vec3<T>> unitVectorRescaled(const Vec3<T>& v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return std::nullopt;
  const T ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
  const T m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
  if (!(m > T(0))) return std::nullopt;
  const Vec3<T> s = v / m;
  return s / length(s);
}
template <class T>
constexpr Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
template <class T>
constexpr Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}
template <class T>
constexpr T maxComponent(const Vec3<T>& v) {
  return v.x > v.y ? (v.x > v.z ? v.x : v.z) : (v.y > v.z ? v.y : v.z);
}
template <class T>
bool isFinite(const Vec3<T>& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
// Rec. 709 luminance of linear RGB.
constexpr float luminance(const Rgb& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

}  // namespace lensrt
