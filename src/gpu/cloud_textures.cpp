#include "gpu/cloud_textures.hpp"

#include "generated/objects.hpp"

#include <GLES3/gl3.h>

#include <vector>

namespace draught::gpu {
namespace {

constexpr int kUnits[3] = {contract::kCloudPointsSampler.unit, contract::kCloudAttrsSampler.unit,
                           contract::kCloudNodesSampler.unit};

// Rows of `texels` texels, the last padded with zeros (a partial row cannot be uploaded
// from a shorter array).
template <class T>
void put(unsigned& tex, int& rows, int unit, GLenum internal, GLenum type, const std::vector<T>& data) {
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
  } else {
    glBindTexture(GL_TEXTURE_2D, tex);
  }
  std::vector<T> padded(std::size_t(need) * std::size_t(kCloudTextureWidth) * 4, T(0));
  std::copy(data.begin(), data.end(), padded.begin());
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kCloudTextureWidth, need, GL_RGBA, type, padded.data());
}

}  // namespace

CloudTextures::CloudTextures() = default;

CloudTextures::~CloudTextures() {
  for (unsigned& t : tex_)
    if (t) glDeleteTextures(1, &t);
}

void CloudTextures::upload(const CloudTexels& tx) {
  put(tex_[0], rows_[0], kUnits[0], GL_RGBA32F, GL_FLOAT, tx.points);
  put(tex_[1], rows_[1], kUnits[1], GL_RGBA16F, GL_HALF_FLOAT, tx.attrs);
  put(tex_[2], rows_[2], kUnits[2], GL_RGBA32F, GL_FLOAT, tx.nodes);
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
