#include "core/pointcloud/cloud_texels.hpp"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace draught {

int cloud_texture_rows(std::size_t texels) {
  return std::max(1, int((texels + std::size_t(kCloudTextureWidth) - 1) / std::size_t(kCloudTextureWidth)));
}

namespace {

// Checked before anything is written, rather than trusted to whoever built the tree: the
// shader would render a larger leaf with points silently missing.
void check_tree(const PointCloud& cloud, const CloudBvh& bvh, int max_leaf) {
  if (bvh.order.size() != cloud.size())
    throw std::invalid_argument("cloud textures: the tree holds " + std::to_string(bvh.order.size()) +
                                " points, the cloud " + std::to_string(cloud.size()));
  const auto big =
      std::find_if(bvh.nodes.begin(), bvh.nodes.end(), [&](const BvhNode& n) { return n.count > max_leaf; });
  if (big != bvh.nodes.end())
    throw std::invalid_argument("cloud textures: a leaf of " + std::to_string(big->count) +
                                " points passes the limit of " + std::to_string(max_leaf) +
                                " (the shader's leaf loop reads CLOUD_LEAF_SIZE = " + std::to_string(kCloudLeafSize) +
                                ")");
}

// Cloud r's points (in leaf order) and nodes (indices made absolute) into arrays already
// sized to hold them; its box and smallest support into r.
void write_cloud(CloudTexels& tx, CloudRange& r, const PointCloud& cloud, const CloudBvh& bvh) {
  r.root = bvh.nodes.empty() ? -1 : r.first_node;
  r.min_support = 0;
  r.lo = r.hi = glm::vec3(0.0f);
  if (!bvh.nodes.empty()) {
    r.lo = bvh.nodes.front().lo;
    r.hi = bvh.nodes.front().hi;
  }
  float* p = tx.points.data() + 4 * std::size_t(r.first_point);
  std::uint16_t* a = tx.attrs.data() + 4 * std::size_t(r.first_point);
  float min_r = INFINITY;
  for (std::uint32_t i : bvh.order) {
    const glm::vec3& c = cloud.position[i];
    const float R = bvh.support_scale * cloud.radius_of(i);
    min_r = std::min(min_r, R);
    *p++ = c.x, *p++ = c.y, *p++ = c.z, *p++ = R;
    const float temp = cloud.temperature.empty() ? 0.0f : cloud.temperature[i];
    const glm::vec3 col = cloud.color.empty() ? glm::vec3(0.0f) : cloud.color[i];
    *a++ = glm::packHalf1x16(temp), *a++ = glm::packHalf1x16(col.r), *a++ = glm::packHalf1x16(col.g),
    *a++ = glm::packHalf1x16(col.b);
  }
  if (!cloud.position.empty()) r.min_support = min_r;
  float* q = tx.nodes.data() + 8 * std::size_t(r.first_node);
  for (const BvhNode& n : bvh.nodes) {
    // Absolute indices: children among all clouds' nodes, points among all clouds' points.
    const float index = float(n.leaf() ? n.index + r.first_point : n.index + r.first_node);
    for (float v : {n.lo.x, n.lo.y, n.lo.z, index, n.hi.x, n.hi.y, n.hi.z, float(n.count)}) *q++ = v;
  }
}

}  // namespace

CloudRange CloudTexels::append(const PointCloud& cloud, const CloudBvh& bvh, int max_leaf) {
  if (int(clouds.size()) >= kMaxClouds)
    throw std::invalid_argument("cloud textures: a cloud beyond the " + std::to_string(kMaxClouds) + " a scene may hold");
  check_tree(cloud, bvh, max_leaf);
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
  points.resize(points.size() + 4 * cloud.size());
  attrs.resize(attrs.size() + 4 * cloud.size());
  nodes.resize(nodes.size() + 8 * bvh.nodes.size());
  write_cloud(*this, r, cloud, bvh);
  clouds.push_back(r);
  return r;
}

CloudRange CloudTexels::rewrite(std::size_t k, const PointCloud& cloud, const CloudBvh& bvh, int max_leaf) {
  if (k >= clouds.size()) throw std::invalid_argument("cloud textures: no cloud " + std::to_string(k) + " to rewrite");
  check_tree(cloud, bvh, max_leaf);
  CloudRange& r = clouds[k];
  if (std::size_t(r.point_count) != cloud.size() || std::size_t(r.node_count) != bvh.nodes.size())
    throw std::invalid_argument("cloud textures: cloud " + std::to_string(k) + " holds " +
                                std::to_string(r.point_count) + " points and " + std::to_string(r.node_count) +
                                " nodes, its new tree " + std::to_string(cloud.size()) + " and " +
                                std::to_string(bvh.nodes.size()));
  write_cloud(*this, r, cloud, bvh);
  return r;
}

void CloudTexels::truncate(std::size_t count) {
  if (count >= clouds.size()) return;
  const CloudRange& r = clouds[count];
  points.resize(4 * std::size_t(r.first_point));
  attrs.resize(4 * std::size_t(r.first_point));
  nodes.resize(8 * std::size_t(r.first_node));
  clouds.resize(count);
}

CloudTexelSpan& CloudTexelSpan::operator|=(const CloudTexelSpan& o) {
  auto join = [](std::size_t& f, std::size_t& e, std::size_t of, std::size_t oe) {
    if (of >= oe) return;
    if (f >= e) f = of, e = oe;
    else f = std::min(f, of), e = std::max(e, oe);
  };
  join(points_first, points_end, o.points_first, o.points_end);
  join(nodes_first, nodes_end, o.nodes_first, o.nodes_end);
  return *this;
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
