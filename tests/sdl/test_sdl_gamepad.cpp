// The SDL2 adapter, driven by hand-made SDL_Events (no SDL_Init, no controller needed).
#include "platform/sdl_gamepad.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught {
namespace {

SDL_Event sensor(SDL_JoystickID which, SDL_SensorType type, double t, glm::dvec3 v, bool hardware_time = true) {
  SDL_Event e{};
  e.csensor.type = SDL_CONTROLLERSENSORUPDATE;
  e.csensor.which = which;
  e.csensor.sensor = type;
  e.csensor.timestamp = Uint32(t * 1e3);
  e.csensor.timestamp_us = hardware_time ? Uint64(t * 1e6) : 0;
  e.csensor.data[0] = float(v.x), e.csensor.data[1] = float(v.y), e.csensor.data[2] = float(v.z);
  return e;
}

// The controller held flat, then rolled right side down at 0.5 rad/s for `seconds`.
void roll_right(SdlGamepadInput& in, SDL_JoystickID which, double seconds, bool hardware_time = true) {
  for (int i = 0; i <= int(seconds * 200); ++i) {
    const double t = i / 200.0, angle = i > 0 ? 0.5 * t : 0;
    const glm::dvec3 g = glm::angleAxis(angle, glm::dvec3(0, 0, 1)) * glm::dvec3(0, SDL_STANDARD_GRAVITY, 0);
    EXPECT_TRUE(in.handle(sensor(which, SDL_SENSOR_ACCEL, t, g, hardware_time)));
    EXPECT_TRUE(in.handle(sensor(which, SDL_SENSOR_GYRO, t, {0, 0, i > 0 ? -0.5 : 0}, hardware_time)));
  }
}

double lean_x(GamepadMotionDriver& d) { return (d.sample(0).pose.orientation * glm::dvec3(0, 1, 0)).x; }

TEST(SdlGamepad, SensorEventsTiltTheGlass) {
  for (bool hardware_time : {true, false}) {
    GamepadMotionDriver d;
    SdlGamepadInput in(d);
    roll_right(in, 3, 0.5, hardware_time);
    EXPECT_EQ(in.active(), 3);
    EXPECT_NEAR(tilt_angle(d.sample(0).pose.orientation), 0.25, 0.01);
    EXPECT_GT(lean_x(d), 0.2);
  }
}

TEST(SdlGamepad, FollowsOneControllerUntilItIsRemoved) {
  GamepadMotionDriver d;
  SdlGamepadInput in(d);
  roll_right(in, 3, 0.5);
  const glm::dquat q = d.sample(0).pose.orientation;
  // Another controller lying flat does not disturb the followed one.
  for (int i = 0; i < 100; ++i) {
    in.handle(sensor(4, SDL_SENSOR_ACCEL, 0.5 + i / 200.0, {SDL_STANDARD_GRAVITY, 0, 0}));
    in.handle(sensor(4, SDL_SENSOR_GYRO, 0.5 + i / 200.0, {3, 0, 0}));
  }
  EXPECT_EQ(d.sample(0).pose.orientation, q);
  SDL_Event removed{};
  removed.cdevice.type = SDL_CONTROLLERDEVICEREMOVED;
  removed.cdevice.which = 3;
  EXPECT_TRUE(in.handle(removed));
  EXPECT_EQ(in.active(), -1);
  // The next controller to report takes over from scratch: held flat, the glass is upright.
  in.handle(sensor(4, SDL_SENSOR_ACCEL, 1, {0, SDL_STANDARD_GRAVITY, 0}));
  in.handle(sensor(4, SDL_SENSOR_GYRO, 1, {0, 0, 0}));
  EXPECT_EQ(in.active(), 4);
  EXPECT_LT(tilt_angle(d.sample(0).pose.orientation), 1e-6);
}

TEST(SdlGamepad, OtherEventsAreNotConsumed) {
  GamepadMotionDriver d;
  SdlGamepadInput in(d);
  SDL_Event key{};
  key.type = SDL_KEYDOWN;
  EXPECT_FALSE(in.handle(key));
  EXPECT_FALSE(in.handle(sensor(3, SDL_SENSOR_GYRO_L, 0, {1, 0, 0})));  // a Joy-Con half
  EXPECT_EQ(in.active(), -1);
  SDL_Event added{};  // no controller at that index: nothing opens, nothing breaks
  added.cdevice.type = SDL_CONTROLLERDEVICEADDED;
  added.cdevice.which = 7;
  EXPECT_TRUE(in.handle(added));
}

}  // namespace
}  // namespace draught
