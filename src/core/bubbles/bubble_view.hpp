// Where the rising bubbles appear in the picture. A bubble in the liquid is seen through
// the glass wall (or the liquid surface), which bends the view; so for each bubble the
// pixel whose refracted path passes through it is solved for (Newton on the pixel
// position, tracing with the reference intersector). The renderer then draws each one
// as an instanced sphere impostor there, tinted by what the path went through, and
// skips bubbles hidden by the foam head. The MatCap tier (render.tier matcap) bends no
// view: there a bubble is where the camera's straight line to it meets the picture.
#pragma once

#include "core/scene/frame.hpp"

#include <glm/glm.hpp>

#include <vector>

namespace draught {

struct BubbleSprite {
  glm::vec2 centre{0.0f};  // pixels from the top-left
  float radius = 0;        // pixels (the lens of glass and liquid magnifies)
  glm::vec3 tint{1.0f};    // transmittance from the camera to the bubble
  float distance = 0;      // along the path, metres (for back-to-front drawing)
  int object = -1;         // the vessel (index into FrameState::vessels) whose drink holds it
};

// Sprites for the frame's bubbles at width x height, farthest first.
std::vector<BubbleSprite> bubble_sprites(const FrameState&, int width, int height);

}  // namespace draught
