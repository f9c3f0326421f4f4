#include "core/input/device_motion.hpp"

#include <numbers>

namespace draught {

void DeviceMotionDriver::set_screen_orientation(int degrees) {
  const int d = (((degrees % 360) + 360 + 45) / 90 % 4) * 90;
  // At angle d the device is turned d degrees counter-clockwise (as its user sees it), so the
  // screen's up, in sensor coordinates, is +y turned back clockwise by d.
  mount_ = glm::angleAxis(-d * std::numbers::pi / 180, glm::dvec3(0, 0, 1));
}

}  // namespace draught
