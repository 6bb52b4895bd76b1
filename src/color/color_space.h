// Linear RGB colour spaces: sRGB (Rec. 709 primaries), Rec. 2020 and ACEScg
// (AP1), all with their standard whites, and CIE XYZ itself. Their matrices
// are derived from the primaries' and the white's chromaticities.
#pragma once

#include <optional>
#include <string_view>

#include "core/mat3.h"
#include "core/vec.h"

namespace lensrt {

enum class ColorSpaceId { Srgb, Rec2020, AcesCg, Xyz };

struct ColorSpace {
  ColorSpaceId id;
  std::string_view name;          // as --output-space spells it
  Vec2d red, green, blue, white;  // xy chromaticities
  Mat3d rgbToXyz, xyzToRgb;
};

const ColorSpace& colorSpace(ColorSpaceId id);
// "srgb", "rec2020", "acescg", "xyz".
std::optional<ColorSpaceId> parseColorSpace(std::string_view name);

// The RGB-to-XYZ matrix of primaries and a white (white Y = 1).
Mat3d rgbToXyzMatrix(const Vec2d& red, const Vec2d& green, const Vec2d& blue, const Vec2d& white);

}  // namespace lensrt
