// Helpers shared by the input driver tests (header only).
#pragma once

#include "core/scene/motion.hpp"

#include <cmath>
#include <numbers>

namespace draught::test {

inline constexpr double kG = 9.80665;
inline double deg(double d) { return d * std::numbers::pi / 180; }
inline double to_deg(double r) { return r * 180 / std::numbers::pi; }

// The rotation vector (axis * angle) of a unit quaternion, shortest way round.
inline glm::dvec3 rotation_vector(glm::dquat q) {
  if (q.w < 0) q = -q;
  const glm::dvec3 v(q.x, q.y, q.z);
  const double s = glm::length(v);
  return s < 1e-300 ? glm::dvec3(0.0) : v * (2 * std::atan2(s, q.w) / s);
}

// World angular velocity that takes q0 to q1 in dt.
inline glm::dvec3 rate_between(const glm::dquat& q0, const glm::dquat& q1, double dt) {
  return rotation_vector(q1 * glm::conjugate(q0)) / dt;
}

inline glm::dvec3 glass_axis(const glm::dquat& q) { return q * glm::dvec3(0, 1, 0); }

// A motion sensor following the true orientation q(t) (sensor -> world, +Y up) at `hz`:
// feed(t, gyro, accel) with the body rate since the previous reading plus `bias`, and the
// gravity reaction plus `accel_world(t)` seen in the sensor frame.
template <class Feed, class Orientation, class Accel>
void simulate_imu(Feed feed, Orientation q, double t0, double t1, glm::dvec3 bias, Accel accel_world, double hz = 100) {
  const double dt = 1 / hz;
  for (int i = 0; t0 + i * dt <= t1 + 1e-9; ++i) {
    const double t = t0 + i * dt;
    const glm::dvec3 gyro = rotation_vector(glm::conjugate(q(t - dt)) * q(t)) / dt;
    feed(t, gyro + bias, glm::conjugate(q(t)) * (glm::dvec3(0, kG, 0) + accel_world(t)));
  }
}
template <class Feed, class Orientation>
void simulate_imu(Feed feed, Orientation q, double t0, double t1, glm::dvec3 bias = glm::dvec3(0.0)) {
  simulate_imu(feed, q, t0, t1, bias, [](double) { return glm::dvec3(0.0); });
}

}  // namespace draught::test
