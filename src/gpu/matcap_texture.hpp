// The MatCap tier's lit sphere on the GPU (u_matcap, texture unit 8: src/interface/frame.def):
// the frame's MatCap from core (core/environment/matcap: baked from the surroundings or read
// from matcap.file) as an RGBA16F texture with its chain of box-filtered levels (frost
// reads blurrier ones), uploaded only when core gives another MatCap.
#pragma once

#include "core/environment/matcap.hpp"
#include "core/scene/frame.hpp"

#include <memory>
#include <vector>

namespace draught::gpu {

class MatCapTexture {
 public:
  MatCapTexture();
  ~MatCapTexture();
  MatCapTexture(const MatCapTexture&) = delete;
  MatCapTexture& operator=(const MatCapTexture&) = delete;

  // Makes the frame's MatCap current (a bake or a read when its inputs changed, an upload
  // when the MatCap is another). Throws InputError for a matcap.file that cannot be used.
  void update(const FrameState&);
  void bind() const;
  float max_lod() const { return float(levels_ - 1); }
  int uploads() const { return uploads_; }  // how many MatCaps were uploaded (tests)
  const MatCap* current() const { return current_.get(); }

 private:
  unsigned tex_ = 0;
  int levels_ = 1, uploads_ = 0;
  std::shared_ptr<const MatCap> current_;
};

// What the MatCap tier sees behind the glasses, straight on: the backdrop, the lights and
// the sky are the same for every pixel's line whether a glass stands in front or not, so
// the pass draws them once into a picture of their own (u_matcap_background, unit 9,
// RGBA16F) and reads it per pixel. Drawn again only when the frame's uniform block (the
// camera, the picture's size, the surroundings, the screen) differs from the one it was
// drawn with. Without float render targets it reports itself unusable and the pass
// draws the background inline.
class MatCapBackground {
 public:
  MatCapBackground() = default;
  ~MatCapBackground();
  MatCapBackground(const MatCapBackground&) = delete;
  MatCapBackground& operator=(const MatCapBackground&) = delete;

  // True when the picture of `key` (the frame block's bytes) at width x height is ready
  // to be read; else the caller draws it into the bound target (begin_drawing) and calls
  // done. False from ready() and begin_drawing() alike when float targets are refused.
  bool ready(const void* key, size_t bytes, int width, int height) const;
  // Whether the view of `key` was also the last one offered (so it has held for a frame);
  // remembers it. A view seen once is drawn with its background inline: a moving camera
  // would pay a whole background pass and its copy every frame for nothing.
  bool held(const void* key, size_t bytes, int width, int height);
  // Whether the last two views offered were both new: the camera (or a glass) is moving.
  // Then the background is drawn kMovingScale times smaller each way into a second
  // texture (begin_drawing_small, bind_small) and read with linear filtering: a
  // sixteenth of the shading, a softer background only while things move (the sweep,
  // the sky and the lights change slowly across the picture).
  static constexpr int kMovingScale = 4;
  bool moving() const { return new_views_ >= 2; }
  bool begin_drawing_small(int width, int height);  // binds its framebuffer; width, height: the smaller size
  void bind_small() const;
  int small_draws() const { return small_draws_; }  // (tests)
  bool begin_drawing(int width, int height);  // binds its framebuffer
  void done(const void* key, size_t bytes);
  void bind() const;
  bool usable() const { return usable_; }
  int draws() const { return draws_; }  // how many times it was drawn (tests)

 private:
  unsigned fbo_ = 0, tex_ = 0;
  int width_ = 0, height_ = 0, draws_ = 0;
  bool usable_ = true;
  std::vector<unsigned char> key_;
  std::vector<unsigned char> offered_;  // the last view offered (held)
  int offered_width_ = 0, offered_height_ = 0;
  int new_views_ = 0;  // new views offered in a row
  unsigned fbo_small_ = 0, tex_small_ = 0;
  int small_width_ = 0, small_height_ = 0, small_draws_ = 0;
};

}  // namespace draught::gpu
