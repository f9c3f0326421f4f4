// What the device-motion (phone) and gamepad drivers share: sensor fusion, the mounting of
// the glass on the sensor, the reference heading, and the linear acceleration that sloshes
// the drink when the device is shaken.
#pragma once

#include "core/input/driver.hpp"
#include "core/input/fusion.hpp"

#include <limits>

namespace draught {

struct ImuConfig {
  FusionConfig fusion;
  double accel_gain = 0.5;      // world acceleration (gravity removed) -> glass acceleration
  double accel_deadband = 0.3;  // m/s^2 ignored: sensor noise and small tilt errors leak gravity
  double max_accel = 15;        // m/s^2
};

class ImuDriver : public InputDriver {
 public:
  // Upright glass until the first usable reading. Sampling does not extrapolate: it returns the
  // latest reading's pose, so sensor timestamps need not share the sample clock.
  MotionSample sample(double t) override;
  // The current heading becomes "facing the viewer" (done automatically on the first reading).
  void recenter();
  // Forget everything (filter, bias, heading), e.g. when another device takes over.
  virtual void reset();
  const OrientationFilter& filter() const { return filter_; }

 protected:
  explicit ImuDriver(ImuConfig c) : cfg_(c), filter_(c.fusion) {}
  // One gyro + accelerometer reading in the sensor frame, sensor time t in seconds.
  void reading(double t, const glm::dvec3& gyro, const glm::dvec3& accel);
  glm::dquat mount_{1, 0, 0, 0};  // glass frame -> sensor frame

 private:
  ImuConfig cfg_;
  OrientationFilter filter_;
  glm::dquat heading_{1, 0, 0, 0};  // filter world -> viewer world (a turn about +Y)
  glm::dvec3 accel_{0.0};
  double last_t_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace draught
