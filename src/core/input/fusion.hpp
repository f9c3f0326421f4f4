// Orientation from a gyroscope and an accelerometer: a Mahony-style complementary filter.
// The gyro gives fast, smooth rotation but drifts; the accelerometer knows where "up" is
// but is noisy and shaken. The filter integrates the gyro, pulls roll/pitch towards the
// measured gravity, and learns the gyro bias so a constant offset does not drift the tilt.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace draught {

struct FusionConfig {
  double gravity = 9.80665;      // m/s^2
  double gain = 2.0;             // 1/s: how fast roll/pitch follow the accelerometer
  double bias_gain = 0.3;        // 1/s^2: integral term; learns roll/pitch gyro bias at any time
  double accel_tolerance = 0.2;  // skip the correction when | |a| - g | > this * g (shaking, free fall)
  double still_rate = 0.15;      // rad/s: slower than this (after bias removal) may be "still"
  double still_time = 0.3;       // s of stillness before the whole bias (yaw too) follows the gyro
  double still_bias_rate = 2.0;  // 1/s: how fast it follows while still
  double max_dt = 0.1;           // s: longer gaps (a paused app) integrate as this
};

class OrientationFilter {
 public:
  explicit OrientationFilter(FusionConfig c = {}) : cfg_(c) {}
  // One reading, dt seconds after the previous: gyro in rad/s, accelerometer in m/s^2 (the
  // gravity reaction: +g along the axis pointing up at rest), both in the sensor frame.
  // Non-finite readings are ignored (returns false). The first reading with |a| close to g
  // sets roll and pitch directly, yaw 0.
  bool update(double dt, const glm::dvec3& gyro, const glm::dvec3& accel);
  void reset() { *this = OrientationFilter(cfg_); }

  bool initialized() const { return initialized_; }
  // Sensor frame -> world frame (world +Y up; yaw relative to the first reading).
  const glm::dquat& orientation() const { return q_; }
  const glm::dvec3& bias() const { return bias_; }
  const glm::dvec3& rate() const { return rate_; }  // bias-corrected gyro, sensor frame

 private:
  FusionConfig cfg_;
  bool initialized_ = false;
  glm::dquat q_{1, 0, 0, 0};
  glm::dvec3 bias_{0.0}, rate_{0.0};
  double still_for_ = 0;
};

}  // namespace draught
