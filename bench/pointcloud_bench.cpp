// Point-cloud benchmarks (CPU, one core): the BVH's build and refit at 10k / 100k / 1M
// points, and the float march's cost per ray through the tree against the all-points
// loop, and at 10k against 1M points filling the same blob (equal screen coverage).
// docs/POINT_CLOUDS.md quotes the medians.
#include "core/pointcloud/bvh.hpp"
#include "core/pointcloud/cloud_scene.hpp"
#include "core/pointcloud/cloud_texels.hpp"
#include "core/pointcloud/field.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

using namespace draught;

// n points in a ball of radius 3 cm; their blob radius shrinks with n so that a point's
// support overlaps about as many others at every n (1500 points: 4 mm).
PointCloud ball(std::size_t n) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  PointCloud c;
  c.default_radius = 0.004f * std::cbrt(1500.0f / float(n));
  c.position.reserve(n);
  while (c.size() < n) {
    const glm::vec3 p(u(rng), u(rng), u(rng));
    if (glm::dot(p, p) <= 1.0f) c.position.push_back(0.03f * p);
  }
  return c;
}

const float kScale = float(cloud_support_scale(kCloudThreshold));

void BM_Build(benchmark::State& st) {
  const PointCloud c = ball(std::size_t(st.range(0)));
  for (auto _ : st) benchmark::DoNotOptimize(build_cloud_bvh(c, kScale, int(st.range(1))));
  st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_Build)->Args({10000, 4})->Args({100000, 4})->Args({1000000, 2})->Args({1000000, 4})
    ->Args({1000000, 8})->Unit(benchmark::kMillisecond);

void BM_Refit(benchmark::State& st) {
  const PointCloud c = ball(std::size_t(st.range(0)));
  CloudBvh bvh = build_cloud_bvh(c, kScale);
  for (auto _ : st) {
    refit_cloud_bvh(bvh, c);
    benchmark::DoNotOptimize(bvh.nodes.data());
  }
}
BENCHMARK(BM_Refit)->Arg(1000000)->Unit(benchmark::kMillisecond);

// A 32 x 32 grid of rays from 15 cm over a 9 cm square: the blob fills most of it.
template <bool kTree>
void march_rays(benchmark::State& st, std::size_t n, int leaf) {
  const PointCloud c = ball(n);
  CloudTexels tx;
  const CloudRange r = tx.append(c, build_cloud_bvh(c, kScale, leaf), leaf);  // (the CPU twin reads any leaf size)
  const CloudRef ref = cloud_ref(r);
  const glm::vec3 eye(0.0f, 0.0f, 0.15f);
  int hits = 0, rays = 0;
  for (auto _ : st) {
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const glm::vec3 d = glm::normalize(glm::vec3(-0.045f + 0.09f * (float(x) + 0.5f) / 32.0f,
                                                     -0.045f + 0.09f * (float(y) + 0.5f) / 32.0f, -0.15f));
        const auto h = kTree ? march_cloud(tx, ref, eye, d, 0.0f, 1.0f, false)
                             : march_cloud_all_points(tx, ref, r, eye, d, 0.0f, 1.0f, false);
        hits += bool(h);
        ++rays;
      }
  }
  st.SetItemsProcessed(rays);
  st.counters["hit_fraction"] = double(hits) / double(std::max(rays, 1));
}

void BM_MarchTree(benchmark::State& st) { march_rays<true>(st, std::size_t(st.range(0)), int(st.range(1))); }
BENCHMARK(BM_MarchTree)->Args({10000, 2})->Args({10000, 4})->Args({10000, 8})->Args({1000000, 4})
    ->Unit(benchmark::kMicrosecond);

void BM_MarchAllPoints(benchmark::State& st) { march_rays<false>(st, std::size_t(st.range(0)), 4); }
BENCHMARK(BM_MarchAllPoints)->Arg(10000)->Unit(benchmark::kMillisecond)->Iterations(1);

// A frame's clouds brought up to date when a still cloud of n points sits before a stream
// of 400 points that moves every frame (a pour beside molten glass): CloudScene writes the
// stream's texels only; the whole flatten below is what it did before (every cloud again).
std::vector<CloudFrame> still_and_stream(const std::shared_ptr<const PointCloud>& still, std::uint64_t frame) {
  PointCloud s;
  for (int i = 0; i < 400; ++i) s.position.push_back({0.05f, 0.001f * float(i) - 0.001f * float(frame % 7), 0.0f});
  std::vector<CloudFrame> f(2);
  f[0].points = still;
  f[0].version = 1;
  f[1].points = std::make_shared<const PointCloud>(std::move(s));
  f[1].version = frame + 2;
  return f;
}

void BM_SceneUpdateBesideAStream(benchmark::State& st) {
  const auto still = std::make_shared<const PointCloud>(ball(std::size_t(st.range(0))));
  CloudScene scene;
  std::uint64_t frame = 0;
  scene.update(still_and_stream(still, frame));
  for (auto _ : st) {
    const auto f = still_and_stream(still, ++frame);
    benchmark::DoNotOptimize(scene.update(f));
  }
}
BENCHMARK(BM_SceneUpdateBesideAStream)->Arg(1000000)->Unit(benchmark::kMillisecond);

void BM_FlattenEveryCloudBesideAStream(benchmark::State& st) {
  const auto still = std::make_shared<const PointCloud>(ball(std::size_t(st.range(0))));
  const CloudBvh still_tree = build_cloud_bvh(*still, kScale);
  CloudTexels tx;
  std::uint64_t frame = 0;
  for (auto _ : st) {
    const auto f = still_and_stream(still, ++frame);
    const CloudBvh stream_tree = build_cloud_bvh(*f[1].points, kScale);
    tx.clear();
    tx.append(*still, still_tree);
    tx.append(*f[1].points, stream_tree);
    benchmark::DoNotOptimize(tx.points.data());
  }
}
BENCHMARK(BM_FlattenEveryCloudBesideAStream)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
