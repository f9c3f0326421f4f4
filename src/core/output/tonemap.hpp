// Output transforms, C++ twin of shaders/lib/output/tonemap.glsl: linear light ->
// exposure -> (ACES filmic | clamp) -> sRGB. The reference renderer's pictures go through
// the same transform as the GPU's.
#pragma once

#include "core/params/params.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace draught {

// Narkowicz's fit of the ACES reference rendering transform.
inline double aces_filmic(double x) {
  return std::clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Its inverse on [0, 1]: the linear value aces_filmic maps to y (the root of a quadratic;
// y = 1 has a finite preimage, 7.2, since the fit tends to 1.033). Twin of
// aces_filmic_inverse in lib/output/tonemap.glsl.
inline double aces_filmic_inverse(double y) {
  y = std::clamp(y, 0.0, 1.0);
  const double a = 2.43 * y - 2.51, b = 0.59 * y - 0.03, c = 0.14 * y;
  return std::max(0.0, (-b - std::sqrt(std::max(b * b - 4 * a * c, 0.0))) / (2 * a));
}

inline double srgb_to_linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

inline double linear_to_srgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c < 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// One linear radiance to its 8-bit display value under the render settings.
inline glm::u8vec3 display_rgb8(const glm::dvec3& radiance, const RenderParams& r) {
  glm::u8vec3 out;
  for (int i = 0; i < 3; ++i) {
    double c = radiance[i] * r.exposure;
    if (r.tonemap == int(Tonemap::Aces)) c = aces_filmic(c);
    out[i] = std::uint8_t(std::lround(linear_to_srgb(c) * 255.0));
  }
  return out;
}

}  // namespace draught
