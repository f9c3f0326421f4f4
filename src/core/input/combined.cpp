#include "core/input/combined.hpp"

#include <algorithm>
#include <stdexcept>

namespace draught {

MotionSample CombinedDriver::sample(double t) {
  const MotionSample a = base_->sample(t), b = overlay_->sample(t);
  MotionSample s;
  s.time = t;
  s.pose.orientation = a.pose.orientation * b.pose.orientation;
  // d/dt (A B) gives omega = omega_A + A omega_B (omega_B: the overlay's own world rate).
  s.angular_velocity = a.angular_velocity + a.pose.orientation * b.angular_velocity;
  s.pose.position = a.pose.position + b.pose.position;
  s.linear_acceleration = a.linear_acceleration + b.linear_acceleration;
  return sanitize(s);
}

InputRig make_input_driver(std::string_view name) {
  if (std::find(input_driver_names.begin(), input_driver_names.end(), name) == input_driver_names.end()) {
    std::string msg = "unknown input driver '" + std::string(name) + "'; valid names:";
    for (std::string_view n : input_driver_names) msg += " " + std::string(n);
    throw std::invalid_argument(msg);
  }
  InputRig rig;
  const auto part = [&rig](std::string_view p) -> std::unique_ptr<InputDriver> {
    if (p == "mouse") return std::unique_ptr<InputDriver>(rig.mouse = new MouseDriver());
    if (p == "touch") return std::unique_ptr<InputDriver>(rig.touch = new TouchDriver());
    if (p == "gyro") return std::unique_ptr<InputDriver>(rig.device = new DeviceMotionDriver());
    return std::unique_ptr<InputDriver>(rig.gamepad = new GamepadMotionDriver());
  };
  const std::size_t plus = name.find('+');
  if (plus == std::string_view::npos) {
    rig.driver = part(name);
  } else {
    auto gesture = part(name.substr(0, plus));
    rig.driver = std::make_unique<CombinedDriver>(part(name.substr(plus + 1)), std::move(gesture), std::string(name));
  }
  return rig;
}

}  // namespace draught
