// The scene's decals on the GPU (docs/DECALS.md): each vessel's placements in its
// object record (the decals group of src/interface/objects.def), its walls' arc lengths
// along the profile in a data texture (u_decal_arcs, a row per vessel, as u_knots), and
// every decal image the scene uses in one texture array (u_decal_images: SRGB8_ALPHA8,
// mipmapped, one square layer per image, the images resampled to the layers' size by
// core). Images are read through core/vessel/decal_files, which checked them when they
// were set; the array is rebuilt only when the set of images changes (or a file does),
// arc rows uploaded only when a glass changes. A frame without decals costs nothing: the
// path pass is then compiled without them (Renderer's DECALS variant).
#pragma once

#include "core/io/image.hpp"
#include "core/scene/frame.hpp"
#include "generated/objects.hpp"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace draught::gpu {

// The decal images a frame uses, each once, in the order their layers take (the first
// use, outer wall before inner, object by object).
std::vector<std::string> decal_image_names(const FrameState&);
// Object `row`'s decals group: placements, colours, kinds and layers of the images.
void pack_decals(const FrameState&, int row, contract::ObjectRecord&);
// A vessel's arc-length row: texel k = (s_outer[k], s_inner[k], s_outer[k + 1], s_inner[k + 1]).
std::vector<glm::vec4> pack_decal_arcs(const Vessel&);
// The side of the array's square layers for `count` images whose longest side is
// `longest`: that side (a power of two, at least 64), at most 1024, and smaller for many
// images (the array stays under about 90 MB with its mipmaps).
int decal_layer_size(int count, int longest);

class DecalTextures {
 public:
  DecalTextures();
  ~DecalTextures();
  DecalTextures(const DecalTextures&) = delete;
  DecalTextures& operator=(const DecalTextures&) = delete;

  // Brings the array and the arc rows up to the frame. True when the frame draws a decal.
  bool update(const FrameState&);
  // Binds the array and the arc rows to their units (kDecalImagesSampler, kDecalArcsSampler).
  void bind() const;

  int layer_size() const { return layer_size_; }
  // What the last update did (tests: a still frame uploads nothing).
  int images_uploaded() const { return images_uploaded_; }
  int arc_rows_uploaded() const { return arc_uploads_; }

 private:
  unsigned images_tex_ = 0, arcs_tex_ = 0;
  std::vector<std::shared_ptr<const Image>> images_;  // what the array holds, layer by layer (null: unreadable)
  std::vector<std::string> names_;
  int layer_size_ = 0;
  int arc_capacity_ = 0;
  std::vector<std::vector<glm::vec4>> arcs_;  // what u_decal_arcs holds
  int images_uploaded_ = 0, arc_uploads_ = 0;
};

}  // namespace draught::gpu
