// The droplets' pointer from the viewer's mouse. In a scene with a droplets object the trail
// follows the mouse over the picture: the camera ray through the mouse's pixel meets the
// trail's plane (core/scene/frame.hpp droplet_pointer_at, the web page's mapping too). No
// GL, SDL or ImGui here: the app says what the mouse is doing, so it is tested without a
// window.
#pragma once

#include "core/scene/frame.hpp"

#include <optional>

namespace draught::viewer {

// A mouse motion as the viewer sees it: where (window points from the top-left, as SDL
// reports them), the window's size in points, and what else holds the mouse.
struct MouseMotion {
  double x = 0, y = 0;
  int window_width = 0, window_height = 0;
  bool over_ui = false;       // ImGui wants the mouse (over the panel, a widget held)
  bool dragging_glass = false;  // a button is held and its drag tilts or swirls a glass
  // A timeline plays (its pointer actions move the trail), or --screenshot renders (its
  // picture must not depend on where the system's pointer happens to be).
  bool scripted = false;
};

// The pointer (plane coordinates, m) the trail of `framed`'s droplets object follows for
// this motion, `framed` being the frame as drawn (its view the part of the window the scene
// is framed in). Empty, the trail following the pointer it had, when the scene has no
// droplets, the mouse is over the panel or the overlay, a drag is tilting a glass, the
// frames are scripted, or the ray does not meet the plane ahead of the eye.
std::optional<glm::dvec2> mouse_pointer(const FrameState& framed, const MouseMotion&);

}  // namespace draught::viewer
