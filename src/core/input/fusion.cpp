#include "core/input/fusion.hpp"
#include "core/math/vectors.hpp"

#include <algorithm>
#include <cmath>

namespace draught {

namespace {

// The shortest rotation taking unit vector `from` to unit vector `to`.
glm::dquat from_to(const glm::dvec3& from, const glm::dvec3& to) {
  const double c = glm::dot(from, to);
  if (c < -1 + 1e-12) return glm::dquat(0, 1, 0, 0);  // half a turn; any perpendicular axis
  const glm::dvec3 axis = glm::cross(from, to);
  return glm::normalize(glm::dquat(1 + c, axis.x, axis.y, axis.z));
}
}  // namespace

bool OrientationFilter::update(double dt, const glm::dvec3& gyro, const glm::dvec3& accel) {
  if (!all_finite(gyro) || !all_finite(accel) || !std::isfinite(dt)) return false;
  dt = std::clamp(dt, 0.0, cfg_.max_dt);
  const double g = glm::length(accel);
  const bool gravity_only = std::abs(g - cfg_.gravity) < cfg_.accel_tolerance * cfg_.gravity;
  if (!initialized_) {
    if (!gravity_only) return true;
    q_ = from_to(accel / g, {0, 1, 0});
    initialized_ = true;
    return true;
  }
  glm::dvec3 w = gyro - bias_;
  // Still: the true rate is ~0, so what the gyro reads is bias, including the yaw part the
  // accelerometer cannot see.
  still_for_ = gravity_only && glm::length(w) < cfg_.still_rate ? still_for_ + dt : 0;
  if (still_for_ > cfg_.still_time) bias_ += (gyro - bias_) * std::min(1.0, cfg_.still_bias_rate * dt);
  if (gravity_only) {
    // e rotates the estimated up towards the measured one (Mahony); its integral is bias.
    const glm::dvec3 e = glm::cross(accel / g, glm::inverse(q_) * glm::dvec3(0, 1, 0));
    w += cfg_.gain * e;
    bias_ -= cfg_.bias_gain * dt * e;
  }
  const double angle = glm::length(w) * dt;
  if (angle > 0) q_ = glm::normalize(q_ * glm::angleAxis(angle, w / glm::length(w)));
  rate_ = gyro - bias_;
  return true;
}

}  // namespace draught
