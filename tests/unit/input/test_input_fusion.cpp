// The gyro + accelerometer filter: convergence, bias and drift, bad samples.
#include "core/input/fusion.hpp"

#include "input/test_input_common.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace draught {
namespace {

using namespace test;
const glm::dvec3 kUp(0, kG, 0);

double yaw(const glm::dquat& q) {
  const glm::dvec3 x = q * glm::dvec3(1, 0, 0);
  return std::atan2(-x.z, x.x);
}

TEST(FusionFilter, ConstantTiltConvergesDespiteGyroBias) {
  const glm::dvec3 bias(0.05, -0.05, 0.05);
  const glm::dquat held = glm::angleAxis(deg(30), glm::dvec3(0, 0, 1));  // 30 degrees of roll
  OrientationFilter f;
  for (int i = 0; i < 50; ++i) f.update(0.01, bias, kUp);  // starts upright...
  // ...then the device is rolled while the gyro was not looking: only gravity tells.
  const glm::dvec3 accel = glm::conjugate(held) * kUp;
  double worst_late = 0;
  for (int i = 1; i <= 6000; ++i) {
    f.update(0.01, bias, accel);
    if (i >= 500) worst_late = std::max(worst_late, std::abs(tilt_angle(f.orientation()) - deg(30)));
  }
  EXPECT_LT(to_deg(worst_late), 0.5) << "from 5 s to 60 s";
  EXPECT_LT(glm::length(f.bias() - bias), 0.005);
  EXPECT_LT(std::abs(yaw(f.orientation())), deg(3));
}

TEST(FusionFilter, YawBiasIsLearnedWhileStill) {
  OrientationFilter f;
  for (int i = 0; i < 3000; ++i) f.update(0.01, {0, 0.05, 0}, kUp);  // 30 s; uncorrected: 86 degrees
  EXPECT_LT(std::abs(yaw(f.orientation())), deg(3));
  EXPECT_NEAR(f.bias().y, 0.05, 1e-3);
}

TEST(FusionFilter, RollPitchBiasIsLearnedWhileMoving) {
  // Tilted 30 degrees on a turntable: never still, so only the integral term can learn.
  const glm::dvec3 bias(0.05, 0, -0.05);
  const auto q = [](double t) { return glm::angleAxis(0.5 * t, glm::dvec3(0, 1, 0)) * glm::angleAxis(deg(30), glm::dvec3(1, 0, 0)); };
  OrientationFilter f;
  double worst_late = 0;
  simulate_imu([&](double t, glm::dvec3 g, glm::dvec3 a) {
    f.update(0.01, g, a);
    if (t > 20) worst_late = std::max(worst_late, std::abs(tilt_angle(f.orientation()) - deg(30)));
  }, q, 0, 40, bias);
  EXPECT_LT(to_deg(worst_late), 0.3);
}

TEST(FusionFilter, TracksARotation) {
  OrientationFilter f;
  const auto q = [](double t) { return glm::angleAxis(deg(90) * std::clamp(t, 0.0, 1.0), glm::dvec3(1, 0, 0)); };
  simulate_imu([&](double, glm::dvec3 g, glm::dvec3 a) { f.update(0.01, g, a); }, q, 0, 1.5);
  EXPECT_LT(glm::length(rotation_vector(f.orientation() * glm::conjugate(q(1.5)))), deg(1));
}

TEST(FusionFilter, NonFiniteSamplesAreIgnored) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  OrientationFilter f;
  EXPECT_FALSE(f.update(0.01, {0, 0, 0}, {nan, kG, 0}));
  EXPECT_FALSE(f.initialized());
  const glm::dquat held = glm::angleAxis(deg(20), glm::dvec3(1, 0, 0));
  for (int i = 0; i < 100; ++i) f.update(0.01, {0, 0, 0}, glm::conjugate(held) * kUp);
  const glm::dquat before = f.orientation();
  EXPECT_FALSE(f.update(0.01, {nan, 0, 0}, kUp));
  EXPECT_FALSE(f.update(0.01, {0, 0, 0}, {0, inf, 0}));
  EXPECT_FALSE(f.update(nan, {0, 0, 0}, kUp));
  EXPECT_EQ(f.orientation(), before);
  EXPECT_TRUE(std::isfinite(f.bias().x + f.bias().y + f.bias().z));
  for (int i = 0; i < 100; ++i) f.update(0.01, {0, 0, 0}, glm::conjugate(held) * kUp);
  EXPECT_NEAR(tilt_angle(f.orientation()), deg(20), deg(0.1));
}

TEST(FusionFilter, TimeGapsAreClamped) {
  OrientationFilter f;
  f.update(0, {0, 0, 0}, kUp);
  f.update(10.0, {0, 0, 1}, 3.0 * kUp);  // a 10 s gap at 1 rad/s, shaken: no correction
  EXPECT_NEAR(tilt_angle(f.orientation()), 0.1, 1e-9);  // integrated over max_dt only
  f.update(-5.0, {0, 0, 1}, 3.0 * kUp);  // time went backwards: nothing happens
  EXPECT_NEAR(tilt_angle(f.orientation()), 0.1, 1e-9);
}

TEST(FusionFilter, ShakingDoesNotTiltTheEstimate) {
  OrientationFilter f;
  f.update(0, {0, 0, 0}, kUp);
  for (int i = 0; i < 200; ++i) f.update(0.01, {0, 0, 0}, kUp + glm::dvec3(4 * kG * std::sin(i * 0.5), 0, 0));
  for (int i = 0; i < 100; ++i) f.update(0.01, {0, 0, 0}, glm::dvec3(0.0));  // free fall
  EXPECT_LT(tilt_angle(f.orientation()), deg(0.5));
}

}  // namespace
}  // namespace draught
