#include "core/input/gesture.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {

namespace {
constexpr double kTurn = 2 * std::numbers::pi;

bool usable(double t, double x, double y, Viewport vp) {
  return std::isfinite(t) && std::isfinite(x) && std::isfinite(y) && std::isfinite(vp.height) && vp.height > 0;
}

glm::dquat orientation(double lean_x, double lean_z, double spin) {
  return tilt_orientation(std::hypot(lean_x, lean_z), std::atan2(lean_z, lean_x), spin);
}
}  // namespace

void GestureCore::anchor(double t, Mode mode, std::span<const glm::dvec2> pts) {
  const std::size_t needed = mode == Mode::rest ? 0 : mode == Mode::twist ? 2 : 1;
  if (pts.size() < needed) mode = Mode::rest;
  base_ = target_;
  if (mode == Mode::rest) {
    target_ = base_ = Values{0, 0, std::round(target_[2] / kTurn) * kTurn, 0, 0};
    push(t);
  }
  mode_ = mode;
  anchor_pts_.assign(pts.begin(), pts.begin() + needed);
  twist_sum_ = 0;
  if (needed == 2) twist_last_ = std::atan2(pts[1].y - pts[0].y, pts[1].x - pts[0].x);
}

void GestureCore::track(double t, std::span<const glm::dvec2> pts, Viewport vp) {
  if (mode_ == Mode::rest || pts.size() < anchor_pts_.size() || !(vp.height > 0)) return;
  const auto offset = [&](glm::dvec2 d) {
    const glm::dvec2 o = clamp_length(glm::dvec2(base_[3], base_[4]) + d / vp.height * cfg_.swirl_scale, cfg_.max_offset);
    target_[3] = o.x, target_[4] = o.y;
  };
  const glm::dvec2 d = pts[0] - anchor_pts_[0];
  if (mode_ == Mode::tilt) {
    const glm::dvec2 l = clamp_length(glm::dvec2(base_[0], base_[1]) + d / vp.height * cfg_.full_tilt, cfg_.max_tilt);
    target_[0] = l.x, target_[1] = l.y;
  } else if (mode_ == Mode::swirl) {
    offset(d);
  } else {
    // Accumulate the twist in small wrapped steps so whole turns keep counting. Pixel y
    // points down, so a twist that looks counter-clockwise lowers the angle; it spins
    // the glass counter-clockwise seen from above (+Y).
    const double angle = std::atan2(pts[1].y - pts[0].y, pts[1].x - pts[0].x);
    twist_sum_ += std::remainder(angle - twist_last_, kTurn);
    twist_last_ = angle;
    target_[2] = base_[2] - twist_sum_;
    offset((d + pts[1] - anchor_pts_[1]) * 0.5);
  }
  push(t);
}

void GestureCore::push(double t) {
  // Targets apply at their event times, in order, never before the last sample: the result
  // depends only on the events and the sample times, not on how often sample() is called.
  last_event_ = std::max({std::isfinite(t) ? t : last_event_, last_event_, time_});
  pending_.emplace_back(last_event_, target_);
  if (pending_.size() > 4096) advance(pending_.front().first);  // nobody samples: do not grow
}

void GestureCore::step(double dt) {
  // Error e = x - goal obeys (d/dt + w)^3 e = 0, solved exactly: e = (c0 + c1 t + c2 t^2) e^-wt.
  const double w = 1.0 / std::max(cfg_.time_constant, 1e-4), E = std::exp(-w * dt);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const double e = x_[i] - goal_[i];
    const double c1 = v_[i] + w * e, c2 = 0.5 * (a_[i] + 2 * w * v_[i] + w * w * e);
    const double p = e + (c1 + c2 * dt) * dt, p1 = c1 + 2 * c2 * dt;
    x_[i] = goal_[i] + p * E;
    v_[i] = (p1 - w * p) * E;
    a_[i] = (2 * c2 - 2 * w * p1 + w * w * p) * E;
  }
}

void GestureCore::advance(double t) {
  while (!pending_.empty() && pending_.front().first <= t) {
    step(pending_.front().first - time_);
    time_ = pending_.front().first;
    goal_ = pending_.front().second;
    pending_.pop_front();
  }
  if (t > time_) step(t - time_), time_ = t;
}

MotionSample GestureCore::sample(double t) {
  advance(std::isfinite(t) ? t : time_);
  MotionSample s;
  s.time = t;
  s.pose.orientation = orientation(x_[0], x_[1], x_[2]);
  s.pose.position = {x_[3], 0, x_[4]};
  // omega = 2 dq/dt q*, dq/dt by a central difference along the exact channel velocities.
  const double h = 1e-6;
  const glm::dquat dq = (orientation(x_[0] + v_[0] * h, x_[1] + v_[1] * h, x_[2] + v_[2] * h) -
                         orientation(x_[0] - v_[0] * h, x_[1] - v_[1] * h, x_[2] - v_[2] * h)) / (2 * h);
  const glm::dquat w = dq * glm::conjugate(s.pose.orientation);
  s.angular_velocity = 2.0 * glm::dvec3(w.x, w.y, w.z);
  s.linear_acceleration = {a_[3], 0, a_[4]};
  return sanitize(s);
}

// ---- mouse ----

void MouseDriver::press(double t, MouseButton b, double x, double y, Viewport vp, bool shift) {
  if (!usable(t, x, y, vp)) return;
  pos_ = {x, y};
  (b == MouseButton::left ? left_ : right_) = true;
  if (b == MouseButton::left) shift_ = shift;
  reanchor(t);
}

void MouseDriver::move(double t, double x, double y, Viewport vp) {
  if (!usable(t, x, y, vp)) return;
  pos_ = {x, y};
  core_.track(t, {&pos_, 1}, vp);
}

// A release is never dropped (a stuck button is worse); a bad time means "now".
void MouseDriver::release(double t, MouseButton b) {
  (b == MouseButton::left ? left_ : right_) = false;
  reanchor(t);
}

void MouseDriver::reanchor(double t) {
  using M = GestureCore::Mode;
  core_.anchor(t, right_ || (left_ && shift_) ? M::swirl : left_ ? M::tilt : M::rest, {&pos_, 1});
}

// ---- touch ----

void TouchDriver::down(double t, int id, double x, double y, Viewport vp) {
  if (!usable(t, x, y, vp)) return;
  if (find(id) < ids_.size()) return move(t, id, x, y, vp);
  ids_.push_back(id);
  pts_.emplace_back(x, y);
  if (ids_.size() <= 2) reanchor(t);
}

void TouchDriver::move(double t, int id, double x, double y, Viewport vp) {
  const std::size_t i = find(id);
  if (!usable(t, x, y, vp) || i == ids_.size()) return;
  pts_[i] = {x, y};
  if (i < 2) core_.track(t, active(), vp);
}

void TouchDriver::up(double t, int id) {
  const std::size_t i = find(id);
  if (i == ids_.size()) return;
  ids_.erase(ids_.begin() + i);
  pts_.erase(pts_.begin() + i);
  if (i < 2) reanchor(t);
}

void TouchDriver::cancel(double t) {
  ids_.clear();
  pts_.clear();
  reanchor(t);
}

void TouchDriver::reanchor(double t) {
  using M = GestureCore::Mode;
  core_.anchor(t, ids_.empty() ? M::rest : ids_.size() == 1 ? M::tilt : M::twist, active());
}

}  // namespace draught
