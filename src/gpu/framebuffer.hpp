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

}  // namespace draught::gpu
