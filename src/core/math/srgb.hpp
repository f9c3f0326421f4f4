// sRGB's transfer function (IEC 61966-2-1), the one copy in C++: every 8-bit picture
// read or written, the tone map's last step, the fits that weigh errors as the eye does.
// GLSL twin: linear_to_srgb in shaders/lib/output/tonemap.glsl (the GPU decodes sRGB
// texels itself).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace draught {

// An sRGB-encoded value in [0, 1] to linear light.
inline double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

// Linear light, clamped to [0, 1], to its sRGB encoding.
inline double linear_to_srgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c < 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// An 8-bit sRGB code as linear light (a table of the 256).
inline double srgb8_to_linear(std::uint8_t code) {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = srgb_to_linear(i / 255.0);
    return t;
  }();
  return table[code];
}

// Linear light (clamped to [0, 1]) as the nearest 8-bit sRGB code.
inline std::uint8_t linear_to_srgb8(double c) { return std::uint8_t(std::lround(linear_to_srgb(c) * 255.0)); }

}  // namespace draught
