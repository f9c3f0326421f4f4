// The screen's picture on the GPU (core/environment/screen.hpp): two SRGB8_ALPHA8 textures
// with mipmaps, one drawn from while the other takes the next frame, then swapped. A frame
// is uploaded only when another one comes (frames are compared by identity: a source hands
// out the same object for the same frame), and never into the texture the frame before is
// still being drawn from, so the driver has no draw to wait for before it copies. The web
// page streams its <video> element or camera into the back texture itself
// (begin_external, its own texImage upload, commit_external).
#pragma once

#include "core/scene/frame.hpp"
#include "generated/frame.hpp"

#include <memory>

namespace draught::gpu {

// The screen's members of the Frame block for a width x height picture of the frame:
// the card's rectangle, the picture's texels per metre (card) or per radian of view
// (background), the part of the picture the view shows, the last mip level.
void pack_screen(const FrameState&, int width, int height, contract::FrameBlock&);

class ScreenTexture {
 public:
  ScreenTexture();  // needs a current GLES 3.0 context
  ~ScreenTexture();
  ScreenTexture(const ScreenTexture&) = delete;
  ScreenTexture& operator=(const ScreenTexture&) = delete;

  // Brings the front texture up to the frame's picture: uploads it into the back texture
  // and swaps when it is another frame than the one shown; true when it did. A frame with
  // no picture of its own (external) keeps what the app streamed.
  bool update(const ScreenFrame&);
  // Binds the front texture to its unit (contract::kScreenSampler).
  void bind() const;

  // An app's own frame of width x height: the back texture, made that size (level 0 is
  // the app's to fill, rows top-down as GL_RGBA / GL_UNSIGNED_BYTE); its GL name.
  unsigned begin_external(int width, int height);
  // Makes the back texture's mipmaps and swaps: the app's frame is shown from now on.
  void commit_external();

  int width() const { return slots_[front_].width; }
  int height() const { return slots_[front_].height; }
  unsigned front_texture() const { return slots_[front_].tex; }
  int uploads() const { return uploads_; }  // frames uploaded since it was made

 private:
  struct Slot {
    unsigned tex = 0;
    int width = 0, height = 0;
  };
  void shape(Slot&, int width, int height);  // (re)allocates when the size differs
  Slot slots_[2];
  int front_ = 0;
  std::shared_ptr<const Image> shown_;  // the frame in the front texture (held: its address identifies it)
  int uploads_ = 0;
};

}  // namespace draught::gpu
