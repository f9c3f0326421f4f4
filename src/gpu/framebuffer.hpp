// Offscreen float targets that a GL may not support (half-float colour buffers need
// EXT_color_buffer_half_float or _float in ES 3.0 and WebGL2): one check for every user.
#pragma once

#include <GLES3/gl3.h>

namespace draught::gpu {

// Whether the framebuffer bound now can be drawn into; where it cannot, `fbo` and `tex`
// (its colour texture) are deleted and set to 0, and the caller draws without them.
inline bool framebuffer_complete_or_free(unsigned& fbo, unsigned& tex) {
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE) return true;
  glDeleteFramebuffers(1, &fbo);
  glDeleteTextures(1, &tex);
  fbo = tex = 0;
  return false;
}

// (Re)makes an RGBA16F colour target of width x height, its texture on texture unit
// `unit` filtered by `filter` (GL_NEAREST, GL_LINEAR) and clamped, and binds its
// framebuffer; false, both freed, where it cannot be drawn into.
inline bool make_half_float_target(unsigned& fbo, unsigned& tex, int width, int height, int unit, GLenum filter) {
  if (fbo) glDeleteFramebuffers(1, &fbo);
  if (tex) glDeleteTextures(1, &tex);
  glGenTextures(1, &tex);
  glActiveTexture(GL_TEXTURE0 + GLenum(unit));
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA16F, width, height);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glActiveTexture(GL_TEXTURE0);
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
  return framebuffer_complete_or_free(fbo, tex);
}

}  // namespace draught::gpu
