// One interface for everything that moves the glass: mouse, touch, device gyro,
// gamepad motion sensors, a scripted timeline, or a combination, picked at run time.
#pragma once

#include "core/scene/motion.hpp"

namespace draught {

class InputDriver {
 public:
  virtual ~InputDriver() = default;
  virtual const char* name() const = 0;
  // The glass's motion at time t (seconds; calls come with non-decreasing t).
  virtual MotionSample sample(double t) = 0;
};

}  // namespace draught
