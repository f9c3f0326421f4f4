// Feeds SDL2 game controller motion sensors to a GamepadMotionDriver. The app forwards every
// SDL_Event; this opens controllers as they appear, enables their gyro and accelerometer,
// and follows one controller at a time (the first to report motion).
#pragma once

#include "core/input/gamepad_motion.hpp"

#include <SDL2/SDL.h>

#include <vector>

namespace draught {

class SdlGamepadInput {
 public:
  explicit SdlGamepadInput(GamepadMotionDriver& driver) : driver_(driver) {}
  ~SdlGamepadInput();
  SdlGamepadInput(const SdlGamepadInput&) = delete;
  SdlGamepadInput& operator=(const SdlGamepadInput&) = delete;

  // True when the event was a controller event this handled.
  bool handle(const SDL_Event& e);
  SDL_JoystickID active() const { return active_; }  // -1: none yet

 private:
  GamepadMotionDriver& driver_;
  std::vector<SDL_GameController*> open_;
  SDL_JoystickID active_ = -1;
};

}  // namespace draught
