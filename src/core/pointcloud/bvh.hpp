// The BVH over a point cloud's support spheres (centre c_i, support radius
// R_i = support_scale * radius_of(i)): a Morton-code tree built top-down on radix-sorted
// codes (each node splits its range where the highest differing bit of its codes flips;
// by count where that would go deeper than kCloudMaxDepth), leaves of at most leaf_size
// points that are contiguous in `order`. Nodes are depth-first: an inner node's left child
// is the next node. docs/POINT_CLOUDS.md says why this builder and what it costs.
#pragma once

#include "core/pointcloud/cloud.hpp"
#include "generated/constants.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace draught {

inline constexpr int kCloudLeafSize = contract::kCloudLeafSize;
inline constexpr int kCloudMaxDepth = contract::kCloudMaxDepth;

struct BvhNode {
  glm::vec3 lo{0.0f}, hi{0.0f};  // box around the support spheres below it
  int index = 0;                 // inner: the right child; leaf: first entry of order
  int count = 0;                 // 0: inner node (left child = this + 1); > 0: a leaf of count points
  bool leaf() const { return count > 0; }
};

struct CloudBvh {
  std::vector<BvhNode> nodes;       // depth-first; root 0; empty for an empty cloud
  std::vector<std::uint32_t> order; // leaf order -> the point's index in the cloud
  float support_scale = 1.0f;       // R_i = support_scale * radius_of(i)
  int leaf_size = kCloudLeafSize;
  int depth = 0;                    // levels below the root, at most kCloudMaxDepth
  double built_area = 0;            // sum of the inner nodes' box areas when built (the rebuild rule)
};

// Builds the tree (throws std::invalid_argument for leaf_size outside 1 .. 64 or a
// support_scale that is not positive and finite).
CloudBvh build_cloud_bvh(const PointCloud&, float support_scale, int leaf_size = kCloudLeafSize);

// The points moved (the same count, the same order): every box again bottom-up, the
// topology kept. Throws std::invalid_argument when the count differs.
void refit_cloud_bvh(CloudBvh&, const PointCloud&);

// The sum of the inner nodes' box surface areas: a traversal's expected cost grows with
// it (the SAH's argument).
double cloud_bvh_area(const CloudBvh&);

// The rule for animated clouds: rebuild when the count changed or a refit left the inner
// boxes' area more than kCloudRebuildGrowth times the built tree's (the boxes have grown
// into each other); else refit. Returns true when it rebuilt.
inline constexpr double kCloudRebuildGrowth = 1.5;
bool update_cloud_bvh(CloudBvh&, const PointCloud&);

}  // namespace draught
