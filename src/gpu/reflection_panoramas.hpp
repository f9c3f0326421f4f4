// env.reflections: each glass's surroundings (the other objects, the floor, the lights,
// the sky, a screen card) rendered from its middle without it by the path pass's
// PANORAMA variant into one layer of an RGBA16F array texture with mipmaps
// (u_reflections, equirectangular), which the picture's reflections off that glass's
// outside look up (lib/environment/reflections.glsl): glasses mirror each other. Drawn
// again env.reflections_rate times per second of scene time (0: every frame), and when
// the size or the number of glasses changes.
#pragma once

#include "core/scene/frame.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught::gpu {

// The panorama's mapping (twin of panorama_st / panorama_dir in
// shaders/lib/environment/reflections.glsl): s across, t up the rows as drawn.
glm::dvec2 panorama_st(const glm::dvec3& d);
glm::dvec3 panorama_dir(const glm::dvec2& st);

class ReflectionPanoramas {
 public:
  ReflectionPanoramas() = default;
  ~ReflectionPanoramas();
  ReflectionPanoramas(const ReflectionPanoramas&) = delete;
  ReflectionPanoramas& operator=(const ReflectionPanoramas&) = delete;

  // How many glasses of this frame get a panorama (0: env.reflections off or no
  // half-float targets on this GL). A transparent picture's are the opaque one's.
  int layers_for(const FrameState&) const;
  // Whether this frame's panoramas must be drawn: none drawn yet, another size or
  // number of glasses, or a new slot of env.reflections_rate (every frame at 0).
  bool due(const FrameState&, int layers) const;
  // Makes the texture for `layers` panoramas `width` wide (height half), if it is not
  // that already; false where half-float targets cannot be drawn into.
  bool prepare(int width, int layers);
  // Binds layer k's framebuffer (viewport width x height).
  void begin_layer(int k);
  // After every layer: the mip chain, and the slot they were drawn for.
  void finish(const FrameState&);
  void bind() const;
  int width() const { return width_; }
  int height() const { return width_ / 2; }
  int layers() const { return layers_; }
  float max_lod() const;
  int draws() const { return draws_; }  // layers drawn since creation (tests)
  // Level 0 of layer k, RGBA floats, rows bottom-up (tests).
  std::vector<float> read(int layer) const;

 private:
  double slot(const FrameState&) const;
  unsigned tex_ = 0, fbo_ = 0;
  int width_ = 0, layers_ = 0, draws_ = 0;
  bool usable_ = true, drawn_ = false;
  double slot_ = 0;
};

}  // namespace draught::gpu
