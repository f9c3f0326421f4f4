#include "pointer.hpp"

namespace draught::viewer {

std::optional<glm::dvec2> mouse_pointer(const FrameState& framed, const MouseMotion& m) {
  if (m.over_ui || m.dragging_glass || m.scripted) return std::nullopt;
  // A window point's pixel centre, as picking takes it.
  return droplet_pointer_at(framed, m.x + 0.5, m.y + 0.5, m.window_width, m.window_height);
}

}  // namespace draught::viewer
