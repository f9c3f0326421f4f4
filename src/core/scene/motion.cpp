#include "core/scene/motion.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {

glm::dvec3 limit(const glm::dvec3& v, double max_len) {
  if (!all_finite(v)) return glm::dvec3(0.0);
  const double len = glm::length(v);
  return len > max_len ? v * (max_len / len) : v;
}
}  // namespace

double tilt_angle(const glm::dquat& q) {
  const glm::dvec3 axis = q * glm::dvec3(0, 1, 0);
  return std::acos(std::clamp(axis.y / std::max(glm::length(axis), 1e-300), -1.0, 1.0));
}

glm::dquat tilt_orientation(double tilt, double azimuth, double spin) {
  // Leaning towards (cos az, 0, sin az) means rotating +Y about the horizontal axis
  // perpendicular to it: up x lean.
  const glm::dvec3 lean(std::cos(azimuth), 0, std::sin(azimuth));
  const glm::dvec3 axis = glm::cross(glm::dvec3(0, 1, 0), lean);
  return glm::angleAxis(tilt, axis) * glm::angleAxis(spin, glm::dvec3(0, 1, 0));
}

Pose tipped_on_floor(const glm::dquat& q, double foot_radius) {
  Pose p;
  p.orientation = q;
  const glm::dvec3 up_local = glm::inverse(q) * glm::dvec3(0, 1, 0);
  const glm::dvec2 u(up_local.x, up_local.z);
  const double len = glm::length(u);
  if (len < 1e-12) return p;  // upright: stands on its whole foot at the origin
  // The foot rim point lowest in the world stays where it touched the floor.
  const glm::dvec2 c = -foot_radius * u / len;
  const glm::dvec3 contact_local(c.x, 0, c.y);
  const glm::dvec3 axis = q * glm::dvec3(0, 1, 0);
  const glm::dvec2 lean = glm::dvec2(axis.x, axis.z) / std::max(glm::length(glm::dvec2(axis.x, axis.z)), 1e-300);
  const glm::dvec3 contact_world(foot_radius * lean.x, 0, foot_radius * lean.y);
  p.position = contact_world - q * contact_local;
  return p;
}

double reach_below_origin(const glm::dquat& q, const Vessel& v) {
  // A local point p is at world height dot(up, p) (plus the position), up being world up
  // seen from the glass; a ring of radius r at height y reaches down to up.y y - r |up.xz|.
  const glm::dvec3 up = glm::inverse(q) * glm::dvec3(0, 1, 0);
  const double across = std::hypot(up.x, up.z);
  double lowest = up.y * v.height - v.rim_major * across - v.rim_minor;
  for (size_t k = 0; k < v.r_outer.size(); ++k) lowest = std::min(lowest, up.y * double(k) * v.dy - v.r_outer[k] * across);
  return -lowest;
}

Pose resting_on_floor(Pose p, const Vessel& v) {
  p.position.y = std::max(p.position.y, reach_below_origin(p.orientation, v));
  return p;
}

MotionSample sanitize(const MotionSample& in, double max_rate, double max_accel) {
  MotionSample s = in;
  if (!std::isfinite(s.time)) s.time = 0;
  glm::dquat& q = s.pose.orientation;
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  q = std::isfinite(n) && n > 1e-12 ? q / n : glm::dquat(1, 0, 0, 0);
  s.pose.position = limit(s.pose.position, 100.0);
  s.angular_velocity = limit(s.angular_velocity, max_rate);
  s.linear_acceleration = limit(s.linear_acceleration, max_accel);
  return s;
}

}  // namespace draught
