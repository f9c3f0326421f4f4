// A point cloud: metaballs given as points (positions, and optionally radius, temperature,
// colour, velocity per point), as the loaders return it and the BVH, field and renderer
// take it. docs/POINT_CLOUDS.md.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace draught {

struct PointCloud {
  std::vector<glm::vec3> position;     // m
  std::vector<float> radius;           // m: the radius of the point as a lone blob; empty = every point default_radius
  std::vector<float> temperature;      // kelvin; empty = not given
  std::vector<glm::vec3> color;        // linear RGB in [0, 1]; empty = not given
  std::vector<glm::vec3> velocity;     // m/s; empty = not given
  float default_radius = 0.002f;
  std::size_t size() const { return position.size(); }
  float radius_of(std::size_t i) const { return radius.empty() ? default_radius : radius[i]; }
};

// The most points one cloud may have (a million metaballs is the target; four times that
// still fits the GPU's data textures).
inline constexpr std::size_t kMaxCloudPoints = std::size_t(1) << 22;

// The largest point cloud file read: 4M points of a generous binary PLY (double x y z,
// radius, temperature, float velocity, uchar colour: 59 bytes a point) is 250 MB, and a
// 4M-line CSV with long numbers is about as much; 1 GiB leaves room and still refuses a
// mistaken path (a disk image) at once.
inline constexpr std::uintmax_t kMaxPointCloudFileBytes = std::uintmax_t(1) << 30;

}  // namespace draught
