#include "gpu/reflection_panoramas.hpp"

#include "generated/constants.hpp"
#include "generated/frame.hpp"
#include "gpu/framebuffer.hpp"
#include "core/math/constants.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught::gpu {

glm::dvec2 panorama_st(const glm::dvec3& d) {
  const double across = std::abs(d.x) + std::abs(d.z) > 0 ? std::atan2(d.x, -d.z) : 0.0;
  return {0.5 + across * (0.5 / kPi), 1.0 - std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi};
}

glm::dvec3 panorama_dir(const glm::dvec2& st) {
  const double phi = (st.x - 0.5) * 2 * kPi, theta = (1.0 - st.y) * kPi;
  const double r = std::sin(theta);
  return {r * std::sin(phi), std::cos(theta), -r * std::cos(phi)};
}

ReflectionPanoramas::~ReflectionPanoramas() {
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (tex_) glDeleteTextures(1, &tex_);
}

int ReflectionPanoramas::layers_for(const FrameState& f) const {
  if (!f.params.env.reflections || !usable_) return 0;
  return std::min(int(f.vessels.size()), contract::kMaxReflectionPanoramas);
}

double ReflectionPanoramas::slot(const FrameState& f) const {
  const double rate = f.params.env.reflections_rate;
  return rate > 0 ? std::floor(f.time * rate) : f.time;
}

bool ReflectionPanoramas::due(const FrameState& f, int layers) const {
  if (!drawn_ || layers != layers_ || std::clamp(f.params.env.reflections_size, 32, 1024) != width_) return true;
  // Every frame at rate 0 (a still drawn twice is drawn twice: its objects may have moved).
  return f.params.env.reflections_rate <= 0 || slot(f) != slot_;
}

bool ReflectionPanoramas::prepare(int width, int layers) {
  if (!usable_) return false;
  if (tex_ && width == width_ && layers == layers_) return true;
  if (fbo_) glDeleteFramebuffers(1, &fbo_);
  if (tex_) glDeleteTextures(1, &tex_);
  fbo_ = tex_ = 0;
  drawn_ = false;
  const int levels = 1 + int(std::floor(std::log2(double(width))));
  glGenTextures(1, &tex_);
  glActiveTexture(GL_TEXTURE0 + contract::kReflectionsSampler.unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex_);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, levels, GL_RGBA16F, width, width / 2, layers);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_REPEAT);  // across the seam behind
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glActiveTexture(GL_TEXTURE0);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tex_, 0, 0);
  if (!framebuffer_complete_or_free(fbo_, tex_)) {  // no half-float targets
    usable_ = false;
    return false;
  }
  width_ = width;
  layers_ = layers;
  return true;
}

void ReflectionPanoramas::begin_layer(int k) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tex_, 0, k);
  glViewport(0, 0, width_, height());
  ++draws_;
}

void ReflectionPanoramas::finish(const FrameState& f) {
  glActiveTexture(GL_TEXTURE0 + contract::kReflectionsSampler.unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex_);
  glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  glActiveTexture(GL_TEXTURE0);
  drawn_ = true;
  slot_ = slot(f);
}

void ReflectionPanoramas::bind() const {
  glActiveTexture(GL_TEXTURE0 + contract::kReflectionsSampler.unit);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex_);
  glActiveTexture(GL_TEXTURE0);
}

float ReflectionPanoramas::max_lod() const { return width_ > 0 ? float(std::floor(std::log2(double(width_)))) : 0.0f; }

std::vector<float> ReflectionPanoramas::read(int layer) const {
  std::vector<float> px(size_t(width_) * size_t(height()) * 4);
  if (!tex_ || layer < 0 || layer >= layers_) return {};
  GLint target = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tex_, 0, layer);
  glReadPixels(0, 0, width_, height(), GL_RGBA, GL_FLOAT, px.data());
  glBindFramebuffer(GL_FRAMEBUFFER, GLuint(target));
  return px;
}

}  // namespace draught::gpu
