// The cloud BVH (core/pointcloud/bvh, cloud_texels): every point in exactly one leaf,
// every box holding its children's boxes and its points' support spheres (after a refit
// too), on random and degenerate clouds; traversal through the flattened texels equals
// brute force on thousands of random rays; the texels refuse leaves larger than the
// shader reads.
#include "core/pointcloud/bvh.hpp"
#include "core/pointcloud/cloud_texels.hpp"
#include "core/pointcloud/field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

namespace draught {
namespace {

PointCloud random_cloud(std::size_t n, std::uint32_t seed, bool radii = true) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.05f, 0.05f), r(0.001f, 0.004f);
  PointCloud c;
  for (std::size_t i = 0; i < n; ++i) {
    c.position.push_back({u(rng), u(rng), u(rng)});
    if (radii) c.radius.push_back(r(rng));
  }
  return c;
}

bool box_holds(const BvhNode& outer, glm::vec3 lo, glm::vec3 hi) {
  return glm::all(glm::lessThanEqual(outer.lo, lo)) && glm::all(glm::greaterThanEqual(outer.hi, hi));
}

// Checks the invariants; returns the leaves' count.
int check_tree(const CloudBvh& bvh, const PointCloud& c) {
  std::vector<int> seen(c.size(), 0);
  int leaves = 0;
  for (std::size_t j = 0; j < bvh.nodes.size(); ++j) {
    const BvhNode& n = bvh.nodes[j];
    if (n.leaf()) {
      ++leaves;
      EXPECT_LE(n.count, bvh.leaf_size);
      for (int k = n.index; k < n.index + n.count; ++k) {
        const std::uint32_t i = bvh.order[std::size_t(k)];
        ++seen[i];
        const float R = bvh.support_scale * c.radius_of(i);
        EXPECT_TRUE(box_holds(n, c.position[i] - R, c.position[i] + R)) << "node " << j << " point " << i;
      }
    } else {
      EXPECT_GT(n.index, int(j) + 1);
      EXPECT_LT(n.index, int(bvh.nodes.size()));
      const BvhNode &l = bvh.nodes[j + 1], &r = bvh.nodes[std::size_t(n.index)];
      EXPECT_TRUE(box_holds(n, l.lo, l.hi) && box_holds(n, r.lo, r.hi)) << "node " << j;
    }
  }
  for (std::size_t i = 0; i < c.size(); ++i) EXPECT_EQ(seen[i], 1) << "point " << i;
  EXPECT_LE(bvh.depth, kCloudMaxDepth);
  if (!c.position.empty()) {
    EXPECT_EQ(bvh.nodes.size(), std::size_t(2 * leaves - 1));
  }
  return leaves;
}

TEST(PointCloudBvh, InvariantsOnRandomClouds) {
  const float scale = float(cloud_support_scale(0.5));
  for (int leaf : {1, 2, 4, 8}) {
    const PointCloud c = random_cloud(5000, 7u + std::uint32_t(leaf));
    const CloudBvh bvh = build_cloud_bvh(c, scale, leaf);
    const int leaves = check_tree(bvh, c);
    EXPECT_GE(leaves, 5000 / leaf);
  }
}

TEST(PointCloudBvh, InvariantsOnDegenerateClouds) {
  const float scale = float(cloud_support_scale(0.5));
  PointCloud same, line, one, two, none;
  for (int i = 0; i < 1000; ++i) same.position.push_back({0.01f, 0.02f, 0.03f});
  for (int i = 0; i < 1000; ++i) line.position.push_back({0.0f, 0.0001f * float(i), 0.0f});
  one.position.push_back({1.0f, 2.0f, 3.0f});
  two.position = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}};
  for (const PointCloud* c : {&same, &line, &one, &two, &none}) {
    const CloudBvh bvh = build_cloud_bvh(*c, scale);
    check_tree(bvh, *c);
    if (c == &none) {
      EXPECT_TRUE(bvh.nodes.empty());
    }
  }
  // A thousand equal codes split by count: the tree stays within its depth.
  EXPECT_LE(build_cloud_bvh(same, scale, 1).depth, kCloudMaxDepth);
}

TEST(PointCloudBvh, RejectsBadArguments) {
  const PointCloud c = random_cloud(10, 1);
  EXPECT_THROW(build_cloud_bvh(c, 2.2f, 0), std::invalid_argument);
  EXPECT_THROW(build_cloud_bvh(c, 0.0f), std::invalid_argument);
  CloudBvh bvh = build_cloud_bvh(c, 2.2f);
  EXPECT_THROW(refit_cloud_bvh(bvh, random_cloud(11, 1)), std::invalid_argument);
  CloudTexels tx;
  EXPECT_THROW(tx.append(random_cloud(11, 1), bvh), std::invalid_argument);
}

// The shader's leaf loop reads kCloudLeafSize points: the texels refuse a tree with larger
// leaves, naming the leaf and the limit, and append nothing.
TEST(PointCloudBvh, TexelsRefuseLeavesLargerThanTheShaderReads) {
  const PointCloud c = random_cloud(500, 4);
  const CloudBvh wide = build_cloud_bvh(c, 2.2f, 2 * kCloudLeafSize);
  const auto big = std::find_if(wide.nodes.begin(), wide.nodes.end(),
                                [](const BvhNode& n) { return n.count > kCloudLeafSize; });
  ASSERT_NE(big, wide.nodes.end());
  CloudTexels tx;
  try {
    tx.append(c, wide);
    ADD_FAILURE() << "a leaf of " << big->count << " points was taken";
  } catch (const std::invalid_argument& e) {
    const std::string limit = std::to_string(kCloudLeafSize);
    EXPECT_EQ(std::string(e.what()), "cloud textures: a leaf of " + std::to_string(big->count) +
                                         " points passes the limit of " + limit +
                                         " (the shader's leaf loop reads CLOUD_LEAF_SIZE = " + limit + ")");
  }
  EXPECT_TRUE(tx.clouds.empty() && tx.points.empty() && tx.attrs.empty() && tx.nodes.empty());
  // The renderer's trees pass; the CPU twin alone may take larger leaves when asked.
  EXPECT_NO_THROW(tx.append(c, build_cloud_bvh(c, 2.2f)));
  EXPECT_NO_THROW(tx.append(c, wide, 2 * kCloudLeafSize));
}

TEST(PointCloudBvh, RefitKeepsInvariantsAndTheRuleRebuilds) {
  const float scale = float(cloud_support_scale(0.5));
  PointCloud c = random_cloud(4000, 3);
  CloudBvh bvh = build_cloud_bvh(c, scale);
  const std::size_t nodes = bvh.nodes.size();
  // A small motion: refit keeps the topology, the boxes follow.
  std::mt19937 rng(5);
  std::normal_distribution<float> jitter(0.0f, 0.001f);
  for (glm::vec3& p : c.position) p += glm::vec3(jitter(rng), jitter(rng), jitter(rng));
  EXPECT_FALSE(update_cloud_bvh(bvh, c));
  EXPECT_EQ(bvh.nodes.size(), nodes);
  check_tree(bvh, c);
  // Scrambled positions: the refit tree's boxes overlap, its area grows past the rule.
  std::shuffle(c.position.begin(), c.position.end(), rng);
  refit_cloud_bvh(bvh, c);
  check_tree(bvh, c);
  EXPECT_GT(cloud_bvh_area(bvh), kCloudRebuildGrowth * bvh.built_area);
  EXPECT_TRUE(update_cloud_bvh(bvh, c));
  check_tree(bvh, c);
  // Another count: rebuilt.
  c.position.pop_back();
  c.radius.pop_back();
  EXPECT_TRUE(update_cloud_bvh(bvh, c));
  check_tree(bvh, c);
}

TEST(PointCloudBvh, GpuBytesPerPointWithinBudget) {
  const PointCloud c = random_cloud(200000, 11, false);
  for (int leaf : {2, 4, 8}) {
    const CloudBvh bvh = build_cloud_bvh(c, float(cloud_support_scale(0.5)), leaf);
    CloudTexels tx;
    tx.append(c, bvh, leaf);  // (bytes only: the shader would not take leaves of 8)
    const double per_point = double(tx.gpu_bytes()) / double(c.size());
    std::printf("leaf %d: %zu nodes (%.2f per point), %.1f bytes per point\n", leaf, bvh.nodes.size(),
                double(bvh.nodes.size()) / double(c.size()), per_point);
    if (leaf >= kCloudLeafSize) {
      EXPECT_LE(per_point, 64.0);
    }
  }
}

// Every ray: the supports the tree says it crosses are exactly those brute force finds,
// and the nearest entry is brute force's nearest.
TEST(PointCloudBvh, TraversalEqualsBruteForce) {
  const PointCloud a = random_cloud(3000, 21), b = random_cloud(500, 22);
  const float scale = float(cloud_support_scale(0.5));
  CloudTexels tx;
  tx.append(b, build_cloud_bvh(b, scale));  // a first cloud: the second's indices are offset
  const CloudRange r = tx.append(a, build_cloud_bvh(a, scale));
  const CloudRef ref = cloud_ref(r);
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), v(-0.06f, 0.06f);
  int crossing = 0;
  for (int k = 0; k < 4000; ++k) {
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    const glm::vec3 o = glm::vec3(v(rng), v(rng), v(rng)) - 0.2f * d;
    const float tmin = k % 3 == 0 ? 0.2f : 0.0f;  // some rays start inside the cloud
    std::vector<int> brute;
    float nearest = INFINITY;
    for (int i = r.first_point; i < r.first_point + r.point_count; ++i) {
      const glm::vec3 c(tx.points[std::size_t(i) * 4], tx.points[std::size_t(i) * 4 + 1],
                        tx.points[std::size_t(i) * 4 + 2]);
      const float R = tx.points[std::size_t(i) * 4 + 3];
      const glm::vec3 q = o - c;
      const float bq = glm::dot(q, d), disc = bq * bq - (glm::dot(q, q) - R * R);
      if (!(disc > 0.0f)) continue;
      const float t0 = -bq - std::sqrt(disc), t1 = -bq + std::sqrt(disc);
      if (t1 < tmin || t0 > 1.0f) continue;
      brute.push_back(i);
      nearest = std::min(nearest, std::max(t0, tmin));
    }
    std::vector<int> tree = cloud_supports_crossed(tx, ref, o, d, tmin, 1.0f);
    std::sort(tree.begin(), tree.end());
    ASSERT_EQ(tree, brute) << "ray " << k;
    EXPECT_EQ(cloud_next_entry(tx, ref, o, d, tmin, 1.0f), nearest) << "ray " << k;
    crossing += !brute.empty();
  }
  EXPECT_GT(crossing, 1000);
}

}  // namespace
}  // namespace draught
