// Two drivers at once (a gesture on top of device or gamepad motion), and choosing the
// drivers by name at run time.
#pragma once

#include "core/input/device_motion.hpp"
#include "core/input/gamepad_motion.hpp"
#include "core/input/gesture.hpp"

#include <array>
#include <memory>
#include <string>
#include <string_view>

namespace draught {

// The overlay acts in the base's frame, as if the gesture tilted the glass inside the
// device: orientation = base * overlay; positions and accelerations add.
class CombinedDriver : public InputDriver {
 public:
  CombinedDriver(std::unique_ptr<InputDriver> base, std::unique_ptr<InputDriver> overlay, std::string name)
      : base_(std::move(base)), overlay_(std::move(overlay)), name_(std::move(name)) {}
  const char* name() const override { return name_.c_str(); }
  MotionSample sample(double t) override;

 private:
  std::unique_ptr<InputDriver> base_, overlay_;
  std::string name_;
};

inline constexpr std::array<std::string_view, 8> input_driver_names = {
    "mouse", "touch", "gyro", "gamepad", "mouse+gyro", "touch+gyro", "touch+gamepad", "mouse+gamepad"};

// What the app samples (`driver`) and the parts it feeds events to (null when absent). The
// parts are owned by `driver` and live on the heap, so the rig can be moved freely.
struct InputRig {
  std::unique_ptr<InputDriver> driver;
  MouseDriver* mouse = nullptr;
  TouchDriver* touch = nullptr;
  DeviceMotionDriver* device = nullptr;
  GamepadMotionDriver* gamepad = nullptr;
};

// One of input_driver_names (case-sensitive); anything else throws std::invalid_argument
// listing the valid names.
InputRig make_input_driver(std::string_view name);

}  // namespace draught
