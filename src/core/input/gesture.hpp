// Mouse and touch gestures that tilt, spin and swirl the glass. Both feed one GestureCore:
// pointers set targets (lean, spin, offset) and the pose follows them smoothly.
//
// Screen conventions: pixel coordinates with y down; the camera looks along -Z, so screen
// right = world +X and screen down = towards the viewer = world +Z. Event times are seconds
// on the same clock as the sample() times.
#pragma once

#include "core/input/driver.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <span>
#include <utility>
#include <vector>

namespace draught {

struct Viewport {
  double width = 0, height = 0;  // pixels
};

struct GestureConfig {
  double full_tilt = 1.5707963267948966;  // rad of lean for a drag over the viewport height
  double max_tilt = 1.3962634015954636;   // 80 degrees
  double swirl_scale = 0.1;               // m of travel per viewport height
  double max_offset = 0.05;               // m
  // Each smoothed value follows its target with a triple real pole at 1/time_constant
  // (a critically damped spring whose anchor itself lags the target), so position,
  // velocity and acceleration all stay continuous. 0.06 s settles like a 0.08 s spring.
  double time_constant = 0.06;
};

class GestureCore {
 public:
  enum class Mode { rest, tilt, swirl, twist };  // twist: two pointers spin + swirl

  explicit GestureCore(GestureConfig c = {}) : cfg_(c) {}
  // The pointers (or their meaning) changed: keep the current targets and measure further
  // motion from these positions, so adding or lifting a finger never makes the glass jump.
  // Mode::rest sends the glass back upright, at the origin, spin to the nearest whole turn.
  void anchor(double t, Mode mode, std::span<const glm::dvec2> pts);
  void track(double t, std::span<const glm::dvec2> pts, Viewport vp);  // pointers moved
  MotionSample sample(double t);

 private:
  // Channels: lean x, lean z (rad, rotation towards +X / +Z), spin (rad), offset x, z (m).
  using Values = std::array<double, 5>;
  void push(double t);
  void advance(double t);
  void step(double dt);

  GestureConfig cfg_;
  Mode mode_ = Mode::rest;
  Values base_{}, target_{};
  std::vector<glm::dvec2> anchor_pts_;
  double twist_last_ = 0, twist_sum_ = 0;
  std::deque<std::pair<double, Values>> pending_;  // target changes not yet reached by sample()
  double time_ = 0, last_event_ = 0;
  Values goal_{}, x_{}, v_{}, a_{};  // smoothed state at time_, following goal_
};

enum class MouseButton { left, right };

// Left drag tilts; right drag (or left drag started with shift) swirls; release rests.
class MouseDriver : public InputDriver {
 public:
  explicit MouseDriver(GestureConfig c = {}) : core_(c) {}
  void press(double t, MouseButton b, double x, double y, Viewport vp, bool shift = false);
  void move(double t, double x, double y, Viewport vp);
  void release(double t, MouseButton b);
  const char* name() const override { return "mouse"; }
  MotionSample sample(double t) override { return core_.sample(t); }

 private:
  void reanchor(double t);
  GestureCore core_;
  bool left_ = false, right_ = false, shift_ = false;
  glm::dvec2 pos_{0};
};

// One finger tilts like the left mouse button; two fingers spin the glass by their twist and
// swirl it by their midpoint. Further fingers are tracked but ignored until one of the first
// two lifts.
class TouchDriver : public InputDriver {
 public:
  explicit TouchDriver(GestureConfig c = {}) : core_(c) {}
  void down(double t, int id, double x, double y, Viewport vp);
  void move(double t, int id, double x, double y, Viewport vp);
  void up(double t, int id);
  void cancel(double t);  // the platform dropped every touch
  const char* name() const override { return "touch"; }
  MotionSample sample(double t) override { return core_.sample(t); }

 private:
  void reanchor(double t);
  std::size_t find(int id) const { return std::find(ids_.begin(), ids_.end(), id) - ids_.begin(); }
  std::span<const glm::dvec2> active() const { return std::span(pts_).first(std::min<std::size_t>(2, pts_.size())); }
  GestureCore core_;
  std::vector<int> ids_;  // fingers in touch-down order; the first two drive the gesture
  std::vector<glm::dvec2> pts_;
};

}  // namespace draught
