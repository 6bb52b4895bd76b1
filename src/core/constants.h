#pragma once

#include <limits>

namespace lensrt {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr float kPiF = 3.14159265358979323846f;
inline constexpr float kInvPiF = 1.0f / kPiF;
inline constexpr float kInfinityF = std::numeric_limits<float>::infinity();
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace lensrt
