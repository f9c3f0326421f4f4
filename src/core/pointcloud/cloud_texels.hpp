// A scene's point clouds flattened into the texel arrays of the cloud textures
// (src/interface/objects.def: u_cloud_points, u_cloud_attrs, u_cloud_nodes; uploaded by
// gpu/cloud_textures): every cloud's points in its tree's leaf order and its nodes, with
// indices made absolute, appended one after another. The CPU twin of the march
// (core/pointcloud/field.hpp) reads these same arrays.
#pragma once

#include "core/pointcloud/bvh.hpp"
#include "core/pointcloud/cloud.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace draught {

inline constexpr int kCloudTextureWidth = contract::kCloudTextureWidth;
inline constexpr int kMaxClouds = contract::kMaxClouds;

// Where one cloud lies in the shared arrays.
struct CloudRange {
  int root = -1;          // its root node (absolute); -1: an empty cloud
  int first_point = 0;    // its first point texel
  int point_count = 0;
  int first_node = 0;
  int node_count = 0;
  float min_support = 0;  // its smallest support radius (m): the march's step scale
  glm::vec3 lo{0.0f}, hi{0.0f};  // its root box (m)
};

struct CloudTexels {
  std::vector<float> points;        // 4 per point: centre xyz, support radius R
  std::vector<std::uint16_t> attrs; // 4 halves per point: temperature K, linear r, g, b (0: not given)
  std::vector<float> nodes;         // 8 per node: lo xyz, index; hi xyz, count
  std::vector<CloudRange> clouds;

  // Appends a cloud whose tree was built (or refit) for it; throws std::invalid_argument
  // when the tree is not the cloud's (another count), for a kMaxClouds + 1st cloud, when
  // the arrays would pass what a texture of kCloudTextureWidth^2 texels holds, or for a
  // leaf of more than max_leaf points. The shader reads at most kCloudLeafSize points a
  // leaf (CLOUD_LEAF_SIZE) and skips the rest; only arrays for the CPU twin alone (tests,
  // benchmarks of other leaf sizes) may allow more.
  CloudRange append(const PointCloud&, const CloudBvh&, int max_leaf = kCloudLeafSize);
  // Writes cloud k again in place (its points moved, its tree refit or rebuilt to the same
  // number of nodes): the arrays keep their size and the other clouds their texels.
  // Throws std::invalid_argument, changing nothing, when the counts are not cloud k's.
  CloudRange rewrite(std::size_t k, const PointCloud&, const CloudBvh&, int max_leaf = kCloudLeafSize);
  // Keeps the first `count` clouds and their texels.
  void truncate(std::size_t count);
  void clear();
  int point_count() const { return int(points.size() / 4); }
  int node_count() const { return int(nodes.size() / 8); }
  // Bytes the three textures take on the GPU, rows padded to kCloudTextureWidth.
  std::size_t gpu_bytes() const;
};

// The texels [first, end) of each array that differ from an earlier state (node texels:
// two a node), so that an upload can leave the rest where it is.
struct CloudTexelSpan {
  std::size_t points_first = 0, points_end = 0;
  std::size_t nodes_first = 0, nodes_end = 0;
  static CloudTexelSpan all(const CloudTexels& t) {
    return {0, std::size_t(t.point_count()), 0, 2 * std::size_t(t.node_count())};
  }
  bool empty() const { return points_first >= points_end && nodes_first >= nodes_end; }
  // The smallest span holding both.
  CloudTexelSpan& operator|=(const CloudTexelSpan&);
};

// Rows of a texture of `texels` texels, kCloudTextureWidth per row (at least 1).
int cloud_texture_rows(std::size_t texels);

}  // namespace draught
