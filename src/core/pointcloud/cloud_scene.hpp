// A frame's point clouds as the GPU (and the CPU twin of its march) reads them: each
// cloud's tree, kept while its points are unchanged (the same CloudFrame::version), refit
// or rebuilt when they move (update_cloud_bvh's rule), and every cloud flattened into
// one set of texel arrays (core/pointcloud/cloud_texels.hpp), rewritten only where a
// cloud changed.
#pragma once

#include "core/pointcloud/bvh.hpp"
#include "core/pointcloud/cloud_object.hpp"
#include "core/pointcloud/cloud_texels.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace draught {

class CloudScene {
 public:
  // Brings the texels up to these clouds (at most kMaxClouds; more are left out). True
  // when the texels or the ranges changed (the textures need an upload of changed()).
  bool update(const std::vector<CloudFrame>&);
  const CloudTexels& texels() const { return texels_; }
  // The texels the last update wrote: a cloud whose points moved within the same counts
  // is written in place, the others from the first cloud that changed size on.
  const CloudTexelSpan& changed() const { return changed_; }
  // Cloud i's place in the texels (its root, its smallest support, its box).
  const std::vector<CloudRange>& ranges() const { return texels_.clouds; }
  // Cloud i's tree as the last update left it (built or refit).
  const CloudBvh& tree(std::size_t i) const { return entries_.at(i).bvh; }
  // Trees built and refit by the last update (tests: a still frame builds none).
  int built() const { return built_; }
  int refit() const { return refit_; }

 private:
  struct Entry {
    std::uint64_t version = 0;
    float threshold = 0;
    std::shared_ptr<const PointCloud> points;
    CloudBvh bvh;
  };
  std::vector<Entry> entries_;
  CloudTexels texels_;
  CloudTexelSpan changed_;
  int built_ = 0, refit_ = 0;
};

}  // namespace draught
