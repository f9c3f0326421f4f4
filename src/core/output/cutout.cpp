#include "core/output/cutout.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

glm::dvec3 cutout_light(const FrameState& f) {
  const glm::dvec3 eye(f.camera.eye), centre = surroundings_centre(f);
  glm::dvec3 d = centre - eye;
  d = glm::length(d) > 1e-9 ? glm::normalize(d) : glm::dvec3(0.0, 0.0, -1.0);
  const SkyIrradiance& sky = f.environment.sky;
  double t;
  glm::dvec3 n;
  // f.backdrop is the studio's (a transparent picture's geometry leaves it out: scene_geometry).
  if (f.backdrop.present && f.backdrop.intersect(eye, d, 0.0, t, n)) {
    const glm::dvec3 p = eye + t * d;
    return f.backdrop.albedo(p) * (f.lights.irradiance(p, n) + sky.at(n)) / std::numbers::pi;
  }
  return glm::max(sky.at(d), glm::dvec3(0.0)) / std::numbers::pi;
}

Image straight_alpha(const Image& in) {
  Image out = in;
  for (size_t i = 0; i + 3 < out.rgba.size(); i += 4) {
    std::uint8_t* px = &out.rgba[i];
    const double c[3] = {srgb8_to_linear(px[0]), srgb8_to_linear(px[1]), srgb8_to_linear(px[2])};
    const double a = std::max({px[3] / 255.0, c[0], c[1], c[2]});
    if (a <= 0.0) {
      px[0] = px[1] = px[2] = px[3] = 0;
      continue;
    }
    for (int k = 0; k < 3; ++k) px[k] = linear_to_srgb8(c[k] / a);
    px[3] = std::uint8_t(std::lround(a * 255.0));
  }
  return out;
}

}  // namespace draught
