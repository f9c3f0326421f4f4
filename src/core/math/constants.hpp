// Constants of the C++ side (the shaders keep their own in GLSL). One definition, so that
// files compiled together in a unity build (docs/PERFORMANCE.md) do not each bring one.
#pragma once

#include <limits>
#include <numbers>

namespace draught {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDegree = kPi / 180;  // radians
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kGravity = 9.80665;  // m/s^2, standard gravity

}  // namespace draught
