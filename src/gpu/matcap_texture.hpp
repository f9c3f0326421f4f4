// The MatCap tier's lit sphere on the GPU (u_matcap, texture unit 8: src/interface/frame.def):
// the frame's MatCap from core (core/environment/matcap: baked from the surroundings or read
// from matcap.file) as an RGBA16F texture with its chain of box-filtered levels (frost
// reads blurrier ones), uploaded only when core gives another MatCap.
#pragma once

#include "core/environment/matcap.hpp"
#include "core/scene/frame.hpp"

#include <memory>

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

}  // namespace draught::gpu
