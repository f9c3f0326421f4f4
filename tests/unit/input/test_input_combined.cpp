// Runtime selection of input drivers and the gesture-on-device combination.
#include "core/input/combined.hpp"

#include "input/test_input_common.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace draught {
namespace {

using namespace test;

TEST(CombinedInput, EveryNameBuildsItsParts) {
  for (std::string_view name : input_driver_names) {
    const InputRig rig = make_input_driver(name);
    ASSERT_TRUE(rig.driver);
    EXPECT_EQ(rig.driver->name(), name);
    EXPECT_EQ(rig.mouse != nullptr, name.starts_with("mouse"));
    EXPECT_EQ(rig.touch != nullptr, name.starts_with("touch"));
    EXPECT_EQ(rig.device != nullptr, name.ends_with("gyro"));
    EXPECT_EQ(rig.gamepad != nullptr, name.ends_with("gamepad"));
  }
}

TEST(CombinedInput, UnknownNamesListTheValidOnes) {
  for (const char* bad : {"", "Mouse", "gyro+touch", "mouse+", "keyboard"}) {
    try {
      make_input_driver(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      for (std::string_view name : input_driver_names) EXPECT_NE(msg.find(name), std::string::npos) << msg;
    }
  }
}

TEST(CombinedInput, GestureTiltActsInTheDeviceFrame) {
  InputRig rig = make_input_driver("touch+gyro");
  // The phone tilts back 30 degrees (glass leans away) while a finger drags 10 degrees to
  // the right: the glass leans right within the tilted screen, not within the world.
  const auto q = [](double t) { return glm::angleAxis(deg(-30) * std::clamp(t, 0.0, 1.0), glm::dvec3(1, 0, 0)); };
  rig.touch->down(1.0, 0, 400, 300, {800, 600});
  for (int i = 1; i <= 10; ++i) rig.touch->move(1.0 + 0.01 * i, 0, 400 + 6.667 * i, 300, {800, 600});
  std::vector<MotionSample> s;
  simulate_imu([&](double t, glm::dvec3 g, glm::dvec3 a) {
    rig.device->motion(t, g, a);
    if (t > 0.95) s.push_back(rig.driver->sample(t));
  }, q, 0, 3);
  const glm::dquat both = s.back().pose.orientation;
  EXPECT_NEAR(glm::dot(both, rig.device->sample(3).pose.orientation * rig.touch->sample(3).pose.orientation), 1, 1e-12);
  EXPECT_NEAR(glass_axis(both).x, std::sin(deg(10)), 2e-3);  // world order would give sin 10 cos 30
  EXPECT_NEAR(glass_axis(both).z, -std::cos(deg(10)) * std::sin(deg(30)), 1e-2);
  // The combined rate is the rate of the combined orientation.
  for (std::size_t i = 1; i + 1 < s.size(); i += 7) {
    const glm::dvec3 w = rate_between(s[i - 1].pose.orientation, s[i + 1].pose.orientation, 0.02);
    EXPECT_NEAR(glm::length(w - s[i].angular_velocity), 0, 0.02 + 0.05 * glm::length(w)) << "t = " << s[i].time;
  }
}

TEST(CombinedInput, PositionsAndAccelerationsAdd) {
  InputRig rig = make_input_driver("mouse+gamepad");
  for (int i = 0; i <= 100; ++i) rig.gamepad->accel(0.01 * i, {0, kG, 0}), rig.gamepad->gyro(0.01 * i, {0, 0, 0});
  rig.mouse->press(1, MouseButton::right, 400, 300, {800, 600});
  rig.mouse->move(1.01, 460, 300, {800, 600});
  const MotionSample a = rig.driver->sample(1.1);
  EXPECT_GT(a.linear_acceleration.x, 0.01);  // the swirl's own acceleration comes through
  EXPECT_NEAR(rig.driver->sample(3).pose.position.x, 0.01, 1e-6);
}

}  // namespace
}  // namespace draught
