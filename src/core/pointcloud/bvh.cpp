#include "core/pointcloud/bvh.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

// Spreads the low 10 bits of v to every third bit (x: bit 3k).
std::uint32_t spread_bits(std::uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Sorts (code << 32 | index) by code: four 8-bit passes of a least-significant-digit
// radix sort, stable, so equal codes keep the cloud's order (the build is deterministic).
void radix_sort(std::vector<std::uint64_t>& keys) {
  std::vector<std::uint64_t> tmp(keys.size());
  for (int pass = 0; pass < 4; ++pass) {
    const int shift = 32 + 8 * pass;
    std::size_t count[257] = {};
    for (std::uint64_t k : keys) ++count[((k >> shift) & 0xffu) + 1];
    for (int i = 0; i < 256; ++i) count[i + 1] += count[i];
    for (std::uint64_t k : keys) tmp[count[(k >> shift) & 0xffu]++] = k;
    keys.swap(tmp);
  }
}

// Levels of halving that bring count points down to leaves of at most leaf points.
int levels_needed(std::size_t count, int leaf) {
  int l = 0;
  for (std::size_t c = count; c > std::size_t(leaf); c = (c + 1) / 2) ++l;
  return l;
}

struct Builder {
  const PointCloud& cloud;
  const std::vector<std::uint32_t>& codes;  // in leaf order
  CloudBvh& bvh;

  void sphere_box(std::size_t k, glm::vec3& lo, glm::vec3& hi) const {
    const std::uint32_t i = bvh.order[k];
    const float r = bvh.support_scale * cloud.radius_of(i);
    lo = glm::min(lo, cloud.position[i] - r);
    hi = glm::max(hi, cloud.position[i] + r);
  }

  // Emits the subtree of order[b, e) at `depth` and returns its node's index.
  int build(std::size_t b, std::size_t e, int depth) {
    const int self = int(bvh.nodes.size());
    bvh.nodes.emplace_back();
    bvh.depth = std::max(bvh.depth, depth);
    const std::size_t count = e - b;
    if (count <= std::size_t(bvh.leaf_size)) {
      BvhNode n;
      n.lo = glm::vec3(INFINITY);
      n.hi = glm::vec3(-INFINITY);
      for (std::size_t k = b; k < e; ++k) sphere_box(k, n.lo, n.hi);
      n.index = int(b);
      n.count = int(count);
      bvh.nodes[std::size_t(self)] = n;
      return self;
    }
    std::size_t mid = b + count / 2;
    // Split where the highest differing bit of the range's codes flips (a spatial median
    // of the Morton curve), unless that would leave too few levels to halve what remains.
    if (levels_needed(count, bvh.leaf_size) < kCloudMaxDepth - depth && codes[b] != codes[e - 1]) {
      const int bit = 31 - std::countl_zero(codes[b] ^ codes[e - 1]);
      const std::uint32_t mask = 1u << bit;
      mid = std::size_t(std::partition_point(codes.begin() + std::ptrdiff_t(b), codes.begin() + std::ptrdiff_t(e),
                                             [&](std::uint32_t c) { return (c & mask) == 0; }) -
                        codes.begin());
    }
    build(b, mid, depth + 1);
    const int right = build(mid, e, depth + 1);
    BvhNode& n = bvh.nodes[std::size_t(self)];
    const BvhNode &l = bvh.nodes[std::size_t(self + 1)], &r = bvh.nodes[std::size_t(right)];
    n.lo = glm::min(l.lo, r.lo);
    n.hi = glm::max(l.hi, r.hi);
    n.index = right;
    n.count = 0;
    return self;
  }
};

double box_area(const BvhNode& n) {
  const glm::dvec3 e = glm::max(glm::dvec3(n.hi - n.lo), glm::dvec3(0.0));
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

}  // namespace

CloudBvh build_cloud_bvh(const PointCloud& cloud, float support_scale, int leaf_size) {
  if (leaf_size < 1 || leaf_size > 64)
    throw std::invalid_argument("cloud BVH: leaf_size " + std::to_string(leaf_size) + ", expected 1 .. 64");
  if (!(support_scale > 0.0f) || !std::isfinite(support_scale))
    throw std::invalid_argument("cloud BVH: support_scale " + std::to_string(support_scale) +
                                ", expected a positive finite number");
  const std::size_t n = cloud.size();
  // Indices are stored as exact floats on the GPU; 2^24 - 1 is the last exact one.
  if (n >= (std::size_t(1) << 24))
    throw std::invalid_argument("cloud BVH: " + std::to_string(n) + " points, expected fewer than 2^24");
  if (levels_needed(n, leaf_size) > kCloudMaxDepth)
    throw std::invalid_argument("cloud BVH: " + std::to_string(n) + " points need more than " +
                                std::to_string(kCloudMaxDepth) + " levels of leaves of " + std::to_string(leaf_size));
  CloudBvh bvh;
  bvh.support_scale = support_scale;
  bvh.leaf_size = leaf_size;
  if (n == 0) return bvh;
  // Morton codes of the centres, quantised to 1024 cells per axis of their bounds.
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : cloud.position) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 ext = hi - lo;
  const glm::vec3 scale = glm::vec3(1023.0f) / glm::max(ext, glm::vec3(1e-30f));
  std::vector<std::uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::uvec3 q = glm::uvec3(glm::clamp((cloud.position[i] - lo) * scale, glm::vec3(0.0f), glm::vec3(1023.0f)));
    const std::uint32_t code = (spread_bits(q.x) << 2) | (spread_bits(q.y) << 1) | spread_bits(q.z);
    keys[i] = (std::uint64_t(code) << 32) | std::uint64_t(i);
  }
  radix_sort(keys);
  std::vector<std::uint32_t> codes(n);
  bvh.order.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    codes[k] = std::uint32_t(keys[k] >> 32);
    bvh.order[k] = std::uint32_t(keys[k]);
  }
  // A binary tree of L leaves has 2 L - 1 nodes; leaves hold at least one point.
  bvh.nodes.reserve(2 * ((n + std::size_t(leaf_size) - 1) / std::size_t(leaf_size)) + 64);
  Builder{cloud, codes, bvh}.build(0, n, 0);
  bvh.built_area = cloud_bvh_area(bvh);
  return bvh;
}

void refit_cloud_bvh(CloudBvh& bvh, const PointCloud& cloud) {
  if (cloud.size() != bvh.order.size())
    throw std::invalid_argument("cloud BVH refit: the cloud has " + std::to_string(cloud.size()) +
                                " points, the tree " + std::to_string(bvh.order.size()) + "; rebuild instead");
  // Children follow their parent in depth-first order: walking backwards sees them first.
  for (std::size_t j = bvh.nodes.size(); j-- > 0;) {
    BvhNode& n = bvh.nodes[j];
    if (n.leaf()) {
      n.lo = glm::vec3(INFINITY);
      n.hi = glm::vec3(-INFINITY);
      for (int k = n.index; k < n.index + n.count; ++k) {
        const std::uint32_t i = bvh.order[std::size_t(k)];
        const float r = bvh.support_scale * cloud.radius_of(i);
        n.lo = glm::min(n.lo, cloud.position[i] - r);
        n.hi = glm::max(n.hi, cloud.position[i] + r);
      }
    } else {
      const BvhNode &l = bvh.nodes[j + 1], &r = bvh.nodes[std::size_t(n.index)];
      n.lo = glm::min(l.lo, r.lo);
      n.hi = glm::max(l.hi, r.hi);
    }
  }
}

double cloud_bvh_area(const CloudBvh& bvh) {
  double a = 0;
  for (const BvhNode& n : bvh.nodes)
    if (!n.leaf()) a += box_area(n);
  return a;
}

bool update_cloud_bvh(CloudBvh& bvh, const PointCloud& cloud) {
  if (cloud.size() == bvh.order.size()) {
    refit_cloud_bvh(bvh, cloud);
    if (cloud_bvh_area(bvh) <= kCloudRebuildGrowth * bvh.built_area) return false;
  }
  bvh = build_cloud_bvh(cloud, bvh.support_scale, bvh.leaf_size);
  return true;
}

}  // namespace draught
