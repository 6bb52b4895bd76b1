#include "color/color_space.h"

#include <array>

namespace lensrt {

namespace {

Vec3d xyzOf(const Vec2d& xy) {
  return {xy.x / xy.y, 1.0, (1 - xy.x - xy.y) / xy.y};
}

ColorSpace make(ColorSpaceId id, std::string_view name, Vec2d r, Vec2d g, Vec2d b, Vec2d w) {
  const Mat3d m = rgbToXyzMatrix(r, g, b, w);
  return {id, name, r, g, b, w, m, *m.inverse()};
}

const std::array<ColorSpace, 4>& spaces() {
  static const std::array<ColorSpace, 4> s{
      make(ColorSpaceId::Srgb, "srgb", {0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}, {0.3127, 0.3290}),
      make(ColorSpaceId::Rec2020, "rec2020", {0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046},
           {0.3127, 0.3290}),
      make(ColorSpaceId::AcesCg, "acescg", {0.713, 0.293}, {0.165, 0.830}, {0.128, 0.044},
           {0.32168, 0.33767}),
      ColorSpace{ColorSpaceId::Xyz, "xyz", {1, 0}, {0, 1}, {0, 0}, {1.0 / 3, 1.0 / 3}, Mat3d{}, Mat3d{}},
  };
  return s;
}

}  // namespace

Mat3d rgbToXyzMatrix(const Vec2d& red, const Vec2d& green, const Vec2d& blue, const Vec2d& white) {
  const Mat3d primaries = Mat3d::columns(xyzOf(red), xyzOf(green), xyzOf(blue));
  // Each primary scaled so that RGB (1, 1, 1) is the white.
  const Vec3d scale = *primaries.inverse() * xyzOf(white);
  return primaries * Mat3d::diagonal(scale);
}

const ColorSpace& colorSpace(ColorSpaceId id) {
  return spaces()[std::size_t(id)];
}

std::optional<ColorSpaceId> parseColorSpace(std::string_view name) {
  for (const ColorSpace& s : spaces())
    if (s.name == name) return s.id;
  return std::nullopt;
}

}  // namespace lensrt
