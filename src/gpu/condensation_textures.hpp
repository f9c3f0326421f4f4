// Condensation on the GPU (docs/CONDENSATION.md): each condensed glass's bead grid and
// fog map (core/condensation/wall_grid) in two data textures, a band of rows per glass
// (u_condensation_beads RGBA32F, unit 13; u_condensation_fog R8 with linear filtering,
// unit 14), and where its band lies in its object record (the condensation group of
// src/interface/objects.def). A band is uploaded only when its glass's condensation has
// changed (a new state version). Frames without condensation cost nothing: the path pass
// is then compiled without it (Renderer's CONDENSATION variant).
#pragma once

#include "core/scene/frame.hpp"
#include "generated/objects.hpp"

#include <cstdint>
#include <vector>

namespace draught::gpu {

// The band of vessel `row`'s condensation in the textures: its place among the frame's
// condensed glasses (a state with a band), -1 for a dry glass or one beyond MAX_CONDENSED.
int condensation_band(const FrameState&, int row);
// Vessel `row`'s condensation group.
void pack_condensation(const FrameState&, int row, contract::ObjectRecord&);

class CondensationTextures {
 public:
  CondensationTextures() = default;
  ~CondensationTextures();
  CondensationTextures(const CondensationTextures&) = delete;
  CondensationTextures& operator=(const CondensationTextures&) = delete;

  // Brings the bands up to the frame. True when the frame shows condensation.
  bool update(const FrameState&);
  void bind() const;
  int bands_uploaded() const { return uploads_; }  // by the last update (tests: a still frame uploads nothing)

 private:
  unsigned beads_tex_ = 0, fog_tex_ = 0;
  int capacity_ = 0;  // bands the textures hold
  std::vector<const CondensationState*> held_;  // what each band holds (with its version)
  std::vector<std::uint64_t> versions_;
  int uploads_ = 0;
};

}  // namespace draught::gpu
