#include "platform/sdl_gamepad.hpp"

#include <algorithm>

namespace draught {

SdlGamepadInput::~SdlGamepadInput() {
  for (SDL_GameController* c : open_) SDL_GameControllerClose(c);
}

bool SdlGamepadInput::handle(const SDL_Event& e) {
  switch (e.type) {
    case SDL_CONTROLLERDEVICEADDED: {  // cdevice.which: a device index
      SDL_GameController* c = SDL_GameControllerOpen(e.cdevice.which);
      if (!c) return true;
      for (SDL_SensorType s : {SDL_SENSOR_GYRO, SDL_SENSOR_ACCEL})
        if (SDL_GameControllerHasSensor(c, s)) SDL_GameControllerSetSensorEnabled(c, s, SDL_TRUE);
      open_.push_back(c);
      return true;
    }
    case SDL_CONTROLLERDEVICEREMOVED: {  // cdevice.which: an instance id
      SDL_GameController* c = SDL_GameControllerFromInstanceID(e.cdevice.which);
      if (auto it = std::find(open_.begin(), open_.end(), c); c && it != open_.end()) {
        SDL_GameControllerClose(c);
        open_.erase(it);
      }
      if (e.cdevice.which == active_) active_ = -1;
      return true;
    }
    case SDL_CONTROLLERSENSORUPDATE: {
      const SDL_ControllerSensorEvent& s = e.csensor;
      if (s.sensor != SDL_SENSOR_GYRO && s.sensor != SDL_SENSOR_ACCEL) return false;  // Joy-Con halves
      if (active_ < 0) {
        active_ = s.which;
        driver_.reset();  // the bias and heading belonged to another controller
      }
      if (s.which != active_) return true;
      // The hardware timestamp is finer than SDL_GetTicks when the controller provides one.
      const double t = s.timestamp_us ? s.timestamp_us * 1e-6 : s.timestamp * 1e-3;
      const glm::dvec3 v(s.data[0], s.data[1], s.data[2]);
      s.sensor == SDL_SENSOR_GYRO ? driver_.gyro(t, v) : driver_.accel(t, v);
      return true;
    }
    default:
      return false;
  }
}

}  // namespace draught
