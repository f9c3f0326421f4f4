#include "core/input/imu_driver.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

void ImuDriver::reading(double t, const glm::dvec3& gyro, const glm::dvec3& accel) {
  if (!std::isfinite(t)) return;
  const bool was_initialized = filter_.initialized();
  if (!filter_.update(std::isnan(last_t_) ? 0 : t - last_t_, gyro, accel)) return;
  last_t_ = std::isnan(last_t_) ? t : std::max(last_t_, t);
  accel_ = accel;
  if (!was_initialized && filter_.initialized()) recenter();
}

void ImuDriver::recenter() {
  // Split the glass pose into a lean (about a horizontal axis) after a twist about its own
  // axis: q = lean * twist, and twist = (w, 0, y, 0) normalised. Undoing the twist as a turn
  // of the world keeps the lean and faces the device the natural way towards the viewer.
  const glm::dquat g = filter_.orientation() * mount_;
  if (g.w * g.w + g.y * g.y < 1e-6) return;  // upside down: no meaningful heading
  heading_ = glm::angleAxis(-2 * std::atan2(g.y, g.w), glm::dvec3(0, 1, 0));
}

void ImuDriver::reset() {
  filter_.reset();
  heading_ = glm::dquat(1, 0, 0, 0);
  accel_ = glm::dvec3(0.0);
  last_t_ = std::numeric_limits<double>::quiet_NaN();
}

MotionSample ImuDriver::sample(double t) {
  MotionSample s;
  s.time = t;
  if (!filter_.initialized()) return sanitize(s);
  const glm::dquat world = heading_ * filter_.orientation();  // sensor -> viewer world
  s.pose.orientation = world * mount_;
  s.angular_velocity = world * filter_.rate();
  // Specific force rotated to the world, minus gravity's reaction = the device's acceleration.
  glm::dvec3 a = world * accel_ - glm::dvec3(0, cfg_.fusion.gravity, 0);
  const double len = glm::length(a);
  s.linear_acceleration = len > cfg_.accel_deadband ? a * ((len - cfg_.accel_deadband) / len * cfg_.accel_gain) : glm::dvec3(0.0);
  return sanitize(s, 60.0, cfg_.max_accel);
}

}  // namespace draught
