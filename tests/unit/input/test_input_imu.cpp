// Device (phone) and gamepad motion drivers: frames, screen rotation, heading, shaking.
#include "core/input/device_motion.hpp"
#include "core/input/gamepad_motion.hpp"

#include "input/test_input_common.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace draught {
namespace {

using namespace test;
const glm::dvec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

// Rotate by `angle` about world `axis` over the first second, starting from q0.
auto turning(glm::dquat q0, glm::dvec3 axis, double angle) {
  return [=](double t) { return glm::angleAxis(angle * std::clamp(t, 0.0, 1.0), axis) * q0; };
}

void feed(DeviceMotionDriver& d, auto q, double t0, double t1, glm::dvec3 bias = glm::dvec3(0.0)) {
  simulate_imu([&](double t, glm::dvec3 g, glm::dvec3 a) { d.motion(t, g, a); }, q, t0, t1, bias);
}

TEST(DeviceMotion, PortraitRollClockwiseLeansRightTiltBackLeansAway) {
  DeviceMotionDriver roll, back;
  // Clockwise as the user sees the screen = negative about +Z (which points at the user).
  feed(roll, turning({1, 0, 0, 0}, kZ, deg(-20)), 0, 2, {0.02, -0.03, 0.01});
  EXPECT_NEAR(tilt_angle(roll.sample(2).pose.orientation), deg(20), deg(0.5));
  EXPECT_GT(glass_axis(roll.sample(2).pose.orientation).x, 0.3);
  feed(back, turning({1, 0, 0, 0}, kX, deg(-30)), 0, 2);  // top edge away from the user
  EXPECT_NEAR(tilt_angle(back.sample(2).pose.orientation), deg(30), deg(0.5));
  EXPECT_LT(glass_axis(back.sample(2).pose.orientation).z, -0.4);
}

TEST(DeviceMotion, ScreenRotationDoesNotFlipTheTilt) {
  for (int angle : {90, 180, 270, -90}) {
    SCOPED_TRACE(angle);
    DeviceMotionDriver d;
    d.set_screen_orientation(angle);
    // The device turned counter-clockwise by `angle`, upright, facing the user.
    const glm::dquat held = glm::angleAxis(deg(angle), kZ);
    feed(d, turning(held, kZ, 0), 0, 1);
    EXPECT_NEAR(std::abs(glm::dot(d.sample(1).pose.orientation, glm::dquat(1, 0, 0, 0))), 1, 1e-6);
    feed(d, turning(held, kZ, deg(-20)), 1, 3);  // rolled clockwise: leans right
    EXPECT_NEAR(tilt_angle(d.sample(3).pose.orientation), deg(20), deg(0.5));
    EXPECT_GT(glass_axis(d.sample(3).pose.orientation).x, 0.3);
  }
  // Turned to landscape while running: once the UI follows, the glass is upright and still
  // faces the viewer.
  DeviceMotionDriver d;
  feed(d, turning({1, 0, 0, 0}, kZ, deg(90)), 0, 2);
  EXPECT_NEAR(tilt_angle(d.sample(2).pose.orientation), deg(90), deg(0.5));
  d.set_screen_orientation(90);
  EXPECT_NEAR(std::abs(glm::dot(d.sample(2).pose.orientation, glm::dquat(1, 0, 0, 0))), 1, 1e-4);
}

TEST(DeviceMotion, RecenterMakesTheCurrentHeadingFaceTheViewer) {
  DeviceMotionDriver d;
  feed(d, turning({1, 0, 0, 0}, kY, deg(90)), 0, 2);  // the user turns round on a chair
  EXPECT_NEAR(std::abs(glm::dot(d.sample(2).pose.orientation, glm::angleAxis(deg(90), kY))), 1, 1e-4);
  d.recenter();
  EXPECT_NEAR(std::abs(glm::dot(d.sample(2).pose.orientation, glm::dquat(1, 0, 0, 0))), 1, 1e-4);
}

TEST(DeviceMotion, ShakingGivesWorldLinearAcceleration) {
  DeviceMotionDriver d;
  const auto rolled = turning(glm::angleAxis(deg(-20), kZ), kZ, 0);
  const auto shake = [](double t) { return glm::dvec3(0, 0, t > 1 && t < 1.05 ? 3.0 : 0.0); };
  simulate_imu([&](double t, glm::dvec3 g, glm::dvec3 a) { d.motion(t, g, a); }, rolled, 0, 1.01, glm::dvec3(0.0), shake);
  // The first reading of the shake: dead band, then gain. Later readings pull the estimate
  // a little (a complementary filter cannot tell a lateral shake from a tilt at once).
  const glm::dvec3 a = d.sample(1.01).linear_acceleration;
  EXPECT_NEAR(a.z, (3 - 0.3) * 0.5, 0.05);
  EXPECT_NEAR(std::hypot(a.x, a.y), 0, 0.05);
  feed(d, rolled, 1.02, 2);
  EXPECT_EQ(glm::length(d.sample(2).linear_acceleration), 0);  // still: nothing leaks
}

TEST(DeviceMotion, BadReadingsAreIgnored) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  DeviceMotionDriver d;
  EXPECT_EQ(d.sample(0).pose.orientation, glm::dquat(1, 0, 0, 0));  // nothing yet: upright
  feed(d, turning({1, 0, 0, 0}, kZ, deg(-20)), 0, 1);
  d.motion(1.01, {nan, 0, 0}, {0, kG, 0});
  d.motion(nan, {0, 0, 0}, {0, kG, 0});
  d.motion(1.02, {0, 0, 0}, {0, nan, 0});
  feed(d, turning({1, 0, 0, 0}, kZ, deg(-20)), 1.03, 2);
  EXPECT_NEAR(tilt_angle(d.sample(2).pose.orientation), deg(20), deg(0.5));
}

TEST(GamepadMotion, FlatIsUprightAndTheGlassTiltsWithTheController) {
  const auto run = [](auto q) {
    GamepadMotionDriver p;
    // SDL sends the two sensors as separate events.
    simulate_imu([&](double t, glm::dvec3 g, glm::dvec3 a) { p.accel(t, a), p.gyro(t, g); }, q, 0, 2);
    return p.sample(2).pose.orientation;
  };
  EXPECT_LT(tilt_angle(run(turning({1, 0, 0, 0}, kZ, 0))), deg(0.1));
  const glm::dquat right = run(turning({1, 0, 0, 0}, kZ, deg(-25)));  // right side down
  EXPECT_NEAR(tilt_angle(right), deg(25), deg(0.5));
  EXPECT_GT(glass_axis(right).x, 0.3);
  const glm::dquat far_up = run(turning({1, 0, 0, 0}, kX, deg(25)));  // far edge raised
  EXPECT_NEAR(tilt_angle(far_up), deg(25), deg(0.5));
  EXPECT_GT(glass_axis(far_up).z, 0.3);
}

TEST(GamepadMotion, GyroBeforeAnyAccelerometerIsHarmless) {
  GamepadMotionDriver p;
  for (int i = 0; i < 10; ++i) p.gyro(0.01 * i, {1, 2, 3});
  EXPECT_FALSE(p.filter().initialized());
  EXPECT_EQ(p.sample(1).pose.orientation, glm::dquat(1, 0, 0, 0));
  p.accel(1, {0, kG, 0});
  p.accel(1, {0, std::numeric_limits<double>::infinity(), 0});  // ignored: keeps the last
  p.gyro(1, {0, 0, 0});
  EXPECT_TRUE(p.filter().initialized());
  EXPECT_LT(tilt_angle(p.sample(1).pose.orientation), 1e-9);
}

}  // namespace
}  // namespace draught
