// A scene's point clouds on the GPU: the texel arrays of core/pointcloud/cloud_texels.hpp
// as the three textures of src/interface/objects.def (u_cloud_points RGBA32F, unit 10;
// u_cloud_attrs RGBA16F, unit 11; u_cloud_nodes RGBA32F, unit 12), kCloudTextureWidth
// texels a row, read by texelFetch (nearest, no mipmaps).
#pragma once

#include "core/pointcloud/cloud_texels.hpp"

namespace draught::gpu {

class CloudTextures {
 public:
  CloudTextures();
  ~CloudTextures();
  CloudTextures(const CloudTextures&) = delete;
  CloudTextures& operator=(const CloudTextures&) = delete;

  // Uploads the rows holding `span` of the arrays (all of them when storage is made again,
  // which happens only when a texture needs more rows than it has).
  void upload(const CloudTexels&, const CloudTexelSpan& span);
  void upload(const CloudTexels& tx) { upload(tx, CloudTexelSpan::all(tx)); }
  void bind() const;
  int uploads() const { return uploads_; }  // how many uploads were made (tests)

 private:
  unsigned tex_[3] = {0, 0, 0};
  int rows_[3] = {0, 0, 0};
  int uploads_ = 0;
};

}  // namespace draught::gpu
