#include "layout.hpp"

#include <algorithm>

namespace draught::viewer {

Rect free_rect(double width, double height, const std::vector<Rect>& covers, double scene_aspect,
               double min_fraction) {
  const Rect window{0, 0, width, height};
  // A largest free rectangle has every side on the window's edge or a cover's: try them all
  // (a panel and an overlay make 6 x 6 edges; a few hundred candidates).
  std::vector<double> xs{0, width}, ys{0, height};
  for (const Rect& c : covers) {
    if (c.empty() || !c.overlaps(window)) continue;
    xs.push_back(std::clamp(c.x0, 0.0, width)), xs.push_back(std::clamp(c.x1, 0.0, width));
    ys.push_back(std::clamp(c.y0, 0.0, height)), ys.push_back(std::clamp(c.y1, 0.0, height));
  }
  const double aspect = std::max(scene_aspect, 1e-3);
  // The height the scene gets in r: its own height, or less where r is too narrow for it.
  const auto scene_height = [&](const Rect& r) { return std::min(r.height(), r.width() / aspect); };
  Rect best;
  double best_size = -1, best_area = -1;
  for (double x0 : xs)
    for (double x1 : xs)
      for (double y0 : ys)
        for (double y1 : ys) {
          const Rect r{x0, y0, x1, y1};
          if (r.empty() || std::any_of(covers.begin(), covers.end(), [&](const Rect& c) { return r.overlaps(c); }))
            continue;
          const double size = scene_height(r), area = r.width() * r.height();
          if (size > best_size || (size == best_size && area > best_area)) best = r, best_size = size, best_area = area;
        }
  if (best_size < min_fraction * std::min(height, width / aspect)) return window;
  return best;
}

PictureRect picture_rect(const Rect& r, double width, double height) {
  if (!(width > 0 && height > 0) || r.empty()) return {};
  return {r.x0 / width, r.y0 / height, r.width() / width, r.height() / height};
}

}  // namespace draught::viewer
