#include "gpu/cloud_textures.hpp"

#include "generated/objects.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <vector>

namespace draught::gpu {
namespace {

constexpr int kUnits[3] = {contract::kCloudPointsSampler.unit, contract::kCloudAttrsSampler.unit,
                           contract::kCloudNodesSampler.unit};

// The rows of texels [first, end) (all of them when the storage is made again), the last
// row padded with zeros (a partial row cannot be uploaded from a shorter array).
template <class T>
void put(unsigned& tex, int& rows, int unit, GLenum internal, GLenum type, const std::vector<T>& data,
         std::size_t first, std::size_t end) {
  const std::size_t texels = data.size() / 4;
  const int need = cloud_texture_rows(texels);
  glActiveTexture(GL_TEXTURE0 + GLenum(unit));
  if (need > rows || !tex) {
    if (tex) glDeleteTextures(1, &tex);  // immutable storage: a new texture for more rows
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexStorage2D(GL_TEXTURE_2D, 1, internal, kCloudTextureWidth, need);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rows = need;
    first = 0, end = texels;
  } else {
    glBindTexture(GL_TEXTURE_2D, tex);
  }
  end = std::min(end, texels);
  if (first >= end) return;
  const std::size_t width = std::size_t(kCloudTextureWidth);
  const std::size_t row0 = first / width, row1 = std::size_t(cloud_texture_rows(end));
  std::vector<T> part((row1 - row0) * width * 4, T(0));
  std::copy(data.begin() + std::ptrdiff_t(row0 * width * 4),
            data.begin() + std::ptrdiff_t(std::min(data.size(), row1 * width * 4)), part.begin());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, GLint(row0), kCloudTextureWidth, GLsizei(row1 - row0), GL_RGBA, type,
                  part.data());
}

}  // namespace

CloudTextures::CloudTextures() = default;

CloudTextures::~CloudTextures() {
  for (unsigned& t : tex_)
    if (t) glDeleteTextures(1, &t);
}

void CloudTextures::upload(const CloudTexels& tx, const CloudTexelSpan& span) {
  put(tex_[0], rows_[0], kUnits[0], GL_RGBA32F, GL_FLOAT, tx.points, span.points_first, span.points_end);
  put(tex_[1], rows_[1], kUnits[1], GL_RGBA16F, GL_HALF_FLOAT, tx.attrs, span.points_first, span.points_end);
  put(tex_[2], rows_[2], kUnits[2], GL_RGBA32F, GL_FLOAT, tx.nodes, span.nodes_first, span.nodes_end);
  glActiveTexture(GL_TEXTURE0);
  ++uploads_;
}

void CloudTextures::bind() const {
  for (int k = 0; k < 3; ++k) {
    glActiveTexture(GL_TEXTURE0 + GLenum(kUnits[k]));
    glBindTexture(GL_TEXTURE_2D, tex_[k]);
  }
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace draught::gpu
