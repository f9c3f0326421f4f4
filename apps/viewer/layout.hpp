// Where the viewer frames the scene: the largest part of the window that the panel and the
// overlay leave free, judged by how big the scene would be drawn there. No GL and no ImGui,
// so it is tested without a window.
#pragma once

#include "core/scene/camera.hpp"

#include <vector>

namespace draught::viewer {

// A rectangle of the window, [x0, x1) x [y0, y1), in pixels from the top-left.
struct Rect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  bool empty() const { return !(x1 > x0 && y1 > y0); }
  bool overlaps(const Rect& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// The free rectangle of a width x height window that shows a scene of this width / height
// (scene_aspect) largest, among those bounded by the window's and the covers' edges; ties
// go to the larger area. Where the covers leave no rectangle of at least min_fraction of
// the window's height that fits a sensible share of the scene, the whole window: the
// scene is then drawn behind them, as large as the window allows.
Rect free_rect(double width, double height, const std::vector<Rect>& covers, double scene_aspect,
               double min_fraction = 0.4);

// The rectangle as the part of the window it is, for FrameState::view.
PictureRect picture_rect(const Rect&, double width, double height);

}  // namespace draught::viewer
