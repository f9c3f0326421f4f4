#include "core/pointcloud/cloud_scene.hpp"

#include "core/pointcloud/field.hpp"

#include <algorithm>

namespace draught {

bool CloudScene::update(const std::vector<CloudFrame>& clouds) {
  built_ = refit_ = 0;
  const std::size_t n = std::min(clouds.size(), std::size_t(kMaxClouds));
  bool changed = n != entries_.size();
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
  }
  if (!changed) return false;
  texels_.clear();
  for (const Entry& e : entries_) texels_.append(*e.points, e.bvh);
  return true;
}

}  // namespace draught
