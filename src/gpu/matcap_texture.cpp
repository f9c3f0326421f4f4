#include "gpu/matcap_texture.hpp"

#include "gpu/framebuffer.hpp"

#include "generated/frame.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <vector>

namespace draught::gpu {

MatCapTexture::MatCapTexture() { glGenTextures(1, &tex_); }

MatCapTexture::~MatCapTexture() { glDeleteTextures(1, &tex_); }

void MatCapTexture::update(const FrameState& f) {
  std::shared_ptr<const MatCap> m = matcap_for(f.params, f.lights, f.backdrop, surroundings_centre(f));
  if (m == current_) return;
  // RGBA rows bottom-up (GL's t up: the sphere's top last), then each level the 2 x 2 box
  // mean of the one before (ES 3.0 cannot generate mipmaps of a float texture it cannot
  // render to), down to one texel: the surroundings' mean.
  int n = m->size;
  std::vector<float> level(size_t(n) * size_t(n) * 4);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const glm::vec3& c = m->at(x, n - 1 - y);
      float* o = &level[(size_t(y) * size_t(n) + size_t(x)) * 4];
      o[0] = c.r, o[1] = c.g, o[2] = c.b, o[3] = 1.0f;
    }
  levels_ = 1;
  for (int s = n; s > 1; s /= 2) ++levels_;
  glDeleteTextures(1, &tex_);  // storage is immutable: a new texture for a new size
  glGenTextures(1, &tex_);
  glActiveTexture(GL_TEXTURE0 + contract::kMatCapSampler.unit);
  glBindTexture(GL_TEXTURE_2D, tex_);
  glTexStorage2D(GL_TEXTURE_2D, levels_, GL_RGBA16F, n, n);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (int l = 0; l < levels_; ++l) {
    glTexSubImage2D(GL_TEXTURE_2D, l, 0, 0, n, n, GL_RGBA, GL_FLOAT, level.data());
    if (n == 1) break;
    const int h = n / 2;
    std::vector<float> next(size_t(h) * size_t(h) * 4);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < h; ++x)
        for (int c = 0; c < 4; ++c) {
          auto at = [&](int i, int j) { return level[(size_t(j) * size_t(n) + size_t(i)) * 4 + size_t(c)]; };
          next[(size_t(y) * size_t(h) + size_t(x)) * 4 + size_t(c)] =
              0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
        }
    level = std::move(next);
    n = h;
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glActiveTexture(GL_TEXTURE0);
  current_ = std::move(m);
  ++uploads_;
}

void MatCapTexture::bind() const {
  glActiveTexture(GL_TEXTURE0 + contract::kMatCapSampler.unit);
  glBindTexture(GL_TEXTURE_2D, tex_);
  glActiveTexture(GL_TEXTURE0);
}

MatCapBackground::~MatCapBackground() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (tex_) glDeleteTextures(1, &tex_);
  if (fbo_small_) glDeleteFramebuffers(1, &fbo_small_);
  if (tex_small_) glDeleteTextures(1, &tex_small_);
}

bool MatCapBackground::ready(const void* key, size_t bytes, int width, int height) const {
  return usable_ && width == width_ && height == height_ && key_.size() == bytes &&
         std::equal(key_.begin(), key_.end(), static_cast<const unsigned char*>(key));
}

bool MatCapBackground::held(const void* key, size_t bytes, int width, int height) {
  const auto* k = static_cast<const unsigned char*>(key);
  const bool same = width == offered_width_ && height == offered_height_ && offered_.size() == bytes &&
                    std::equal(offered_.begin(), offered_.end(), k);
  offered_.assign(k, k + bytes);
  offered_width_ = width;
  offered_height_ = height;
  new_views_ = same ? 0 : new_views_ + 1;
  return same;
}

bool MatCapBackground::begin_drawing_small(int width, int height) {
  if (!usable_) return false;
  if (width != small_width_ || height != small_height_ || !fbo_small_) {
    // (read between its texels)
    if (!make_half_float_target(fbo_small_, tex_small_, width, height, contract::kMatCapBackgroundSampler.unit, GL_LINEAR)) {
      usable_ = false;
      return false;
    }
    small_width_ = width;
    small_height_ = height;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_small_);
  ++small_draws_;
  return true;
}

void MatCapBackground::bind_small() const {
  glActiveTexture(GL_TEXTURE0 + contract::kMatCapBackgroundSampler.unit);
  glBindTexture(GL_TEXTURE_2D, tex_small_);
  glActiveTexture(GL_TEXTURE0);
}

bool MatCapBackground::begin_drawing(int width, int height) {
  if (!usable_) return false;
  if (width != width_ || height != height_ || !fbo_) {
    if (!make_half_float_target(fbo_, tex_, width, height, contract::kMatCapBackgroundSampler.unit, GL_NEAREST)) {
      usable_ = false;  // no half-float targets
      return false;
    }
    width_ = width;
    height_ = height;
  }
  key_.clear();
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  return true;
}

void MatCapBackground::done(const void* key, size_t bytes) {
  const auto* k = static_cast<const unsigned char*>(key);
  key_.assign(k, k + bytes);
  ++draws_;
}

void MatCapBackground::bind() const {
  glActiveTexture(GL_TEXTURE0 + contract::kMatCapBackgroundSampler.unit);
  glBindTexture(GL_TEXTURE_2D, tex_);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace draught::gpu
