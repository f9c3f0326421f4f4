// A phone or tablet's gyro + accelerometer moves the glass as if the drink stood in the
// device. Sensor frame (W3C DeviceMotion / Android): x right, y up along the screen in the
// natural (portrait) orientation, z out of the screen. The glass axis is the screen's "up"
// as the UI is currently shown, so rotating the UI to landscape with the device never flips
// or swaps the tilt: held upright facing the user, either way round, the glass is upright.
#pragma once

#include "core/input/imu_driver.hpp"

namespace draught {

class DeviceMotionDriver : public ImuDriver {
 public:
  explicit DeviceMotionDriver(ImuConfig c = {}) : ImuDriver(c) {}
  // gyro in rad/s, accel in m/s^2 including gravity (W3C accelerationIncludingGravity).
  void motion(double t, const glm::dvec3& gyro, const glm::dvec3& accel) { reading(t, gyro, accel); }
  // window.screen.orientation.angle: 0, 90, 180 or 270 (others round to the nearest).
  void set_screen_orientation(int degrees);
  const char* name() const override { return "gyro"; }
};

}  // namespace draught
