// A random point cloud for the cloud tests: n points in a ball of radius 0.03 m around
// `centre`, blob radius r, hot in the middle (1400 K falling to 1000 K at the edge) and
// coloured by place. The same seed gives the same cloud, so the CPU and GPU twins' tests
// march the same blobs.
#pragma once

#include "core/pointcloud/cloud.hpp"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <random>

namespace draught::test {

inline PointCloud blob(std::size_t n, float r, glm::vec3 centre, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  PointCloud c;
  c.default_radius = r;
  while (c.size() < n) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    if (glm::dot(p, p) > 1.0f) continue;
    c.position.push_back(centre + 0.03f * p);
    c.temperature.push_back(1400.0f - 400.0f * glm::length(p));
    c.color.push_back({0.5f + 0.5f * p.x, 0.5f, 0.5f - 0.4f * p.z});
  }
  return c;
}

}  // namespace draught::test
