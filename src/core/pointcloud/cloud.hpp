// A point cloud: metaballs by position, with optional per-point radius, temperature,
// colour and velocity (docs/pointcloud-tree.md for how it becomes a surface).
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace draught {

struct PointCloud {
  std::vector<glm::vec3> position;  // m
  std::vector<float> radius;        // m: the radius of the point as a lone blob; empty = every point default_radius
  std::vector<float> temperature;   // kelvin; empty = not given
  std::vector<glm::vec3> color;     // linear RGB in [0, 1]; empty = not given
  std::vector<glm::vec3> velocity;  // m/s; empty = not given
  float default_radius = 0.002f;
  std::size_t size() const { return position.size(); }
  float radius_of(std::size_t i) const { return radius.empty() ? default_radius : radius[i]; }
};

}  // namespace draught
