#include "gpu/screen_texture.hpp"

#include "core/scene/frame.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>

namespace draught::gpu {

namespace {
// Every call works on the screen's own unit, so it never disturbs another texture's binding.
void use_unit() { glActiveTexture(GL_TEXTURE0 + contract::kScreenSampler.unit); }
void done() { glActiveTexture(GL_TEXTURE0); }

// Levels down to 1 x 1, as glGenerateMipmap makes them.
int mip_levels(int w, int h) { return 1 + int(std::floor(std::log2(double(std::max({w, h, 1}))))); }
}  // namespace

void pack_screen(const FrameState& f, int width, int height, contract::FrameBlock& b) {
  const ScreenFrame& s = f.screen;
  if (!s.on()) return;
  const int pw = std::max(s.picture_width(), 1), ph = std::max(s.picture_height(), 1);
  b.screen_brightness = float(s.brightness);
  b.screen_max_lod = float(mip_levels(pw, ph) - 1);
  b.screen_center = glm::vec3(s.center);
  b.screen_normal = glm::vec3(s.normal);
  b.screen_half_u = {glm::vec3(s.half_u), float(pw / std::max(2.0 * glm::length(s.half_u), 1e-9))};
  const CameraBasis cam = camera_basis(f, width, height);
  const double pa = double(pw) / ph;
  b.screen_cover = {float(std::min(1.0, cam.aspect / pa)), float(std::min(1.0, pa / cam.aspect))};
  // The view's height (2 tan(vfov / 2) near the middle, in radians) spans that part of it.
  const float per_radian = float(b.screen_cover.y * ph / (2.0 * cam.tan_half_vfov));
  b.screen_half_v = {glm::vec3(s.half_v), per_radian};
}

ScreenTexture::ScreenTexture() {
  // Black until a picture comes (an app's stream that has not started).
  const unsigned char black[4] = {0, 0, 0, 255};
  use_unit();
  for (Slot& slot : slots_) {
    shape(slot, 1, 1);
    glBindTexture(GL_TEXTURE_2D, slot.tex);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, black);
  }
  done();
}

ScreenTexture::~ScreenTexture() {
  for (Slot& slot : slots_) glDeleteTextures(1, &slot.tex);
}

void ScreenTexture::shape(Slot& slot, int w, int h) {
  if (slot.tex && slot.width == w && slot.height == h) return;
  if (slot.tex) glDeleteTextures(1, &slot.tex);
  glGenTextures(1, &slot.tex);
  glBindTexture(GL_TEXTURE_2D, slot.tex);
  glTexStorage2D(GL_TEXTURE_2D, mip_levels(w, h), GL_SRGB8_ALPHA8, w, h);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  slot.width = w;
  slot.height = h;
}

bool ScreenTexture::update(const ScreenFrame& s) {
  if (!s.picture || s.picture == shown_) return false;
  const Image& img = *s.picture;
  use_unit();
  Slot& back = slots_[1 - front_];
  shape(back, img.width, img.height);
  glBindTexture(GL_TEXTURE_2D, back.tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, img.width, img.height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  front_ = 1 - front_;
  shown_ = s.picture;
  ++uploads_;
  done();
  return true;
}

unsigned ScreenTexture::begin_external(int width, int height) {
  use_unit();  // left active: the app's upload goes to the texture bound here
  Slot& back = slots_[1 - front_];
  shape(back, std::max(width, 1), std::max(height, 1));
  glBindTexture(GL_TEXTURE_2D, back.tex);
  return back.tex;
}

void ScreenTexture::commit_external() {
  use_unit();
  glBindTexture(GL_TEXTURE_2D, slots_[1 - front_].tex);
  glGenerateMipmap(GL_TEXTURE_2D);
  front_ = 1 - front_;
  shown_.reset();
  ++uploads_;
  done();
}

void ScreenTexture::bind() const {
  use_unit();
  glBindTexture(GL_TEXTURE_2D, slots_[front_].tex);
  done();
}

}  // namespace draught::gpu
