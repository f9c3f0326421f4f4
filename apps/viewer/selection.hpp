// Choosing the object that input drives. A click (the pointer pressed and released without
// wandering more than a few pixels) picks the object under it, and a click on the floor or
// the sky keeps the selection; a drag tilts the selected object whatever it starts on; Tab
// and Shift+Tab step through the objects. No GL here: the app picks with pick_object.
#pragma once

#include <cmath>

namespace draught::viewer {

// Tells a click from a drag, for one button.
class ClickTracker {
 public:
  static constexpr double kSlop = 4;  // pixels a click may wander (a hand is not still)

  void press(double x, double y) {
    down_ = true;
    dragged_ = false;
    x0_ = x;
    y0_ = y;
  }
  void move(double x, double y) {
    if (down_ && std::hypot(x - x0_, y - y0_) > kSlop) dragged_ = true;
  }
  // True when the press that ends here was a click. The pointer's furthest excursion
  // counts, not where it ends: a drag out and back is still a drag.
  bool release() {
    const bool click = down_ && !dragged_;
    down_ = false;
    return click;
  }

 private:
  bool down_ = false, dragged_ = false;
  double x0_ = 0, y0_ = 0;
};

// The object `step` (+1 or -1) after `selected`, wrapping around `count` objects.
inline int cycle(int selected, int count, int step) {
  if (count <= 0) return 0;
  return ((selected + step) % count + count) % count;
}

}  // namespace draught::viewer
