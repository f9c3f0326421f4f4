#include "core/pointcloud/cloud_texels.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace draught {

int cloud_texture_rows(std::size_t texels) {
  return std::max(1, int((texels + std::size_t(kCloudTextureWidth) - 1) / std::size_t(kCloudTextureWidth)));
}

CloudRange CloudTexels::append(const PointCloud& cloud, const CloudBvh& bvh, int max_leaf) {
  if (int(clouds.size()) >= kMaxClouds)
    throw std::invalid_argument("cloud textures: a cloud beyond the " + std::to_string(kMaxClouds) + " a scene may hold");
  if (bvh.order.size() != cloud.size())
    throw std::invalid_argument("cloud textures: the tree holds " + std::to_string(bvh.order.size()) +
                                " points, the cloud " + std::to_string(cloud.size()));
  // Checked here, before anything is appended, rather than trusted to whoever built the
  // tree: the shader would render a larger leaf with points silently missing.
  const auto big =
      std::find_if(bvh.nodes.begin(), bvh.nodes.end(), [&](const BvhNode& n) { return n.count > max_leaf; });
  if (big != bvh.nodes.end())
    throw std::invalid_argument("cloud textures: a leaf of " + std::to_string(big->count) +
                                " points passes the limit of " + std::to_string(max_leaf) +
                                " (the shader's leaf loop reads CLOUD_LEAF_SIZE = " + std::to_string(kCloudLeafSize) +
                                ")");
  // The GPU reads indices as floats and textures of at most width^2 texels (rows up to
  // the width WebGL2 guarantees): the nodes' two texels a node bound the count.
  const std::size_t limit = std::size_t(kCloudTextureWidth) * std::size_t(kCloudTextureWidth);
  if (size_t(point_count()) + cloud.size() > limit || 2 * (size_t(node_count()) + bvh.nodes.size()) > limit)
    throw std::invalid_argument("cloud textures: " + std::to_string(point_count() + int(cloud.size())) +
                                " points would pass the " + std::to_string(limit) + " texels of a texture");
  CloudRange r;
  r.first_point = point_count();
  r.point_count = int(cloud.size());
  r.first_node = node_count();
  r.node_count = int(bvh.nodes.size());
  r.root = bvh.nodes.empty() ? -1 : r.first_node;
  r.min_support = 0;
  if (!bvh.nodes.empty()) {
    r.lo = bvh.nodes.front().lo;
    r.hi = bvh.nodes.front().hi;
  }
  points.reserve(points.size() + 4 * cloud.size());
  attrs.reserve(attrs.size() + 4 * cloud.size());
  float min_r = INFINITY;
  for (std::uint32_t i : bvh.order) {
    const glm::vec3& c = cloud.position[i];
    const float R = bvh.support_scale * cloud.radius_of(i);
    min_r = std::min(min_r, R);
    points.insert(points.end(), {c.x, c.y, c.z, R});
    const float temp = cloud.temperature.empty() ? 0.0f : cloud.temperature[i];
    const glm::vec3 col = cloud.color.empty() ? glm::vec3(0.0f) : cloud.color[i];
    attrs.insert(attrs.end(), {glm::packHalf1x16(temp), glm::packHalf1x16(col.r), glm::packHalf1x16(col.g),
                               glm::packHalf1x16(col.b)});
  }
  if (!cloud.position.empty()) r.min_support = min_r;
  nodes.reserve(nodes.size() + 8 * bvh.nodes.size());
  for (const BvhNode& n : bvh.nodes) {
    // Absolute indices: children among all clouds' nodes, points among all clouds' points.
    const float index = float(n.leaf() ? n.index + r.first_point : n.index + r.first_node);
    nodes.insert(nodes.end(), {n.lo.x, n.lo.y, n.lo.z, index, n.hi.x, n.hi.y, n.hi.z, float(n.count)});
  }
  clouds.push_back(r);
  return r;
}

void CloudTexels::clear() {
  points.clear();
  attrs.clear();
  nodes.clear();
  clouds.clear();
}

std::size_t CloudTexels::gpu_bytes() const {
  const std::size_t row = std::size_t(kCloudTextureWidth);
  return std::size_t(cloud_texture_rows(std::size_t(point_count()))) * row * (16 + 8) +
         std::size_t(cloud_texture_rows(2 * std::size_t(node_count()))) * row * 16;
}

}  // namespace draught
