#include "core/pointcloud/cloud_scene.hpp"

#include "core/pointcloud/field.hpp"

#include <algorithm>

namespace draught {

bool CloudScene::update(const std::vector<CloudFrame>& clouds) {
  built_ = refit_ = 0;
  changed_ = {};
  const std::size_t n = std::min(clouds.size(), std::size_t(kMaxClouds));
  // Clouds from `reflatten` on are appended again; a changed cloud before it whose counts
  // held is written in place, so a static million points beside a moving stream stay put.
  std::size_t reflatten = std::min(n, entries_.size());
  bool changed = n != entries_.size();
  std::vector<std::size_t> in_place;
  entries_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const CloudFrame& c = clouds[i];
    Entry& e = entries_[i];
    if (e.points && e.version == c.version && e.threshold == c.threshold) continue;
    changed = true;
    const PointCloud& points = c.points ? *c.points : PointCloud{};
    const float scale = float(cloud_support_scale(c.threshold));
    // A new cloud, another surface level (other supports) or another count: a new tree;
    // the same points moved: refit, or rebuild when the boxes have grown into each other.
    if (!e.points || e.threshold != c.threshold || e.bvh.order.size() != points.size() ||
        e.bvh.support_scale != scale) {
      e.bvh = build_cloud_bvh(points, scale);
      ++built_;
    } else {
      if (update_cloud_bvh(e.bvh, points)) ++built_;
      else ++refit_;
    }
    e.points = c.points ? c.points : std::make_shared<const PointCloud>();
    e.version = c.version;
    e.threshold = c.threshold;
    if (i < reflatten && std::size_t(texels_.clouds[i].point_count) == points.size() &&
        std::size_t(texels_.clouds[i].node_count) == e.bvh.nodes.size())
      in_place.push_back(i);
    else
      reflatten = std::min(reflatten, i);
  }
  if (!changed) return false;
  for (std::size_t k : in_place) {
    if (k >= reflatten) break;
    const CloudRange& r = texels_.rewrite(k, *entries_[k].points, entries_[k].bvh);
    changed_ |= {std::size_t(r.first_point), std::size_t(r.first_point + r.point_count), 2 * std::size_t(r.first_node),
                 2 * std::size_t(r.first_node + r.node_count)};
  }
  texels_.truncate(reflatten);
  const CloudTexelSpan kept = CloudTexelSpan::all(texels_);
  for (std::size_t i = reflatten; i < n; ++i) texels_.append(*entries_[i].points, entries_[i].bvh);
  changed_ |= {kept.points_end, std::size_t(texels_.point_count()), kept.nodes_end, 2 * std::size_t(texels_.node_count())};
  return true;
}

}  // namespace draught
