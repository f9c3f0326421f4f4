// A game controller's motion sensors move the glass, as SDL2 reports them: gyro in rad/s,
// accelerometer in m/s^2 with gravity, axes +X right, +Y up, +Z towards the player with the
// controller held flat. Held flat = upright glass; the frames coincide (+Z is towards the
// viewer in both). No SDL here: src/platform/sdl_gamepad.* feeds it.
#pragma once

#include "core/input/imu_driver.hpp"

#include <cmath>

namespace draught {

class GamepadMotionDriver : public ImuDriver {
 public:
  explicit GamepadMotionDriver(ImuConfig c = {}) : ImuDriver(c) {}
  // SDL delivers the two sensors as separate events: the gyro steps the filter with the
  // latest accelerometer reading.
  void gyro(double t, const glm::dvec3& rad_per_s) { reading(t, rad_per_s, accel_); }
  void accel(double /*t*/, const glm::dvec3& m_per_s2) {
    if (std::isfinite(m_per_s2.x + m_per_s2.y + m_per_s2.z)) accel_ = m_per_s2;  // NaN/Inf: keep the last
  }
  void reset() override {
    ImuDriver::reset();
    accel_ = glm::dvec3(0.0);
  }
  const char* name() const override { return "gamepad"; }

 private:
  glm::dvec3 accel_{0.0};
};

}  // namespace draught
