// Output transforms, C++ twin of shaders/lib/output/tonemap.glsl: linear light ->
// exposure -> (ACES filmic | clamp) -> sRGB. The reference renderer's pictures and the
// GPU's supersampled ones (core/output/resolve) go through the same transform as the
// GPU's single samples.
#pragma once

#include "core/math/srgb.hpp"
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

// One channel of linear light already times the exposure to its 8-bit display code: the
// tone map (`tonemap`: Tonemap), then sRGB. Twin of output_transform in the GLSL.
inline std::uint8_t display_code(double c, int tonemap) {
  if (!(c > 0.0)) c = 0.0;  // (and NaN)
  if (tonemap == int(Tonemap::Aces)) c = aces_filmic(std::min(c, 1e30));
  return linear_to_srgb8(c);
}

// One linear radiance to its 8-bit display value under the render settings.
inline glm::u8vec3 display_rgb8(const glm::dvec3& radiance, const RenderParams& r) {
  glm::u8vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = display_code(radiance[i] * r.exposure, r.tonemap);
  return out;
}

}  // namespace draught
