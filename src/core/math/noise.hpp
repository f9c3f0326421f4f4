// C++ twin of shaders/lib/common/noise.glsl (hash13, value_noise), in float as the
// shader computes it, so the reference sees the same micro-bubble field as the picture.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace draught {

inline float hash13(glm::vec3 p) {
  p = glm::fract(p * 0.1031f);
  p += glm::dot(p, glm::vec3(p.z, p.y, p.x) + 31.32f);
  const float v = (p.x + p.y) * p.z;
  return v - std::floor(v);
}

inline float value_noise(glm::vec3 x) {
  const glm::vec3 i = glm::floor(x);
  glm::vec3 f = x - i;
  f = f * f * (3.0f - 2.0f * f);
  auto h = [&](float a, float b, float c) { return hash13(i + glm::vec3(a, b, c)); };
  const float x00 = glm::mix(h(0, 0, 0), h(1, 0, 0), f.x), x10 = glm::mix(h(0, 1, 0), h(1, 1, 0), f.x);
  const float x01 = glm::mix(h(0, 0, 1), h(1, 0, 1), f.x), x11 = glm::mix(h(0, 1, 1), h(1, 1, 1), f.x);
  return glm::mix(glm::mix(x00, x10, f.y), glm::mix(x01, x11, f.y), f.z);
}

}  // namespace draught
