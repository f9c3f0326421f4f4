// Mouse and touch gestures: directions, clamping, smoothing, re-anchoring, bad events.
#include "core/input/gesture.hpp"

#include "input/test_input_common.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace draught {
namespace {

using test::deg;
using test::glass_axis;
const Viewport kVp{800, 600};

TEST(GestureMouse, DragLeansTheWayThePointerGoesAndClamps) {
  MouseDriver m;
  m.press(0, MouseButton::left, 400, 300, kVp);
  m.move(0.01, 550, 300, kVp);  // right by a quarter of the height: 22.5 degrees towards +X
  const MotionSample s = m.sample(2);
  EXPECT_NEAR(tilt_angle(s.pose.orientation), deg(22.5), deg(0.01));
  EXPECT_GT(glass_axis(s.pose.orientation).x, 0.3);
  EXPECT_NEAR(glass_axis(s.pose.orientation).z, 0, 1e-9);
  EXPECT_NEAR(glm::length(s.pose.position), 0, 1e-12);
  m.move(2.01, 400, 400, kVp);  // down instead: towards the viewer
  EXPECT_GT(glass_axis(m.sample(4).pose.orientation).z, 0.2);
  EXPECT_NEAR(glass_axis(m.sample(4).pose.orientation).x, 0, 1e-9);
  m.move(4.01, 400, 1500, kVp);  // two viewport heights: 180 degrees asked, 80 allowed
  EXPECT_NEAR(tilt_angle(m.sample(6).pose.orientation), deg(80), 1e-6);
}

TEST(GestureMouse, ReleaseReturnsUprightWithoutOvershoot) {
  MouseDriver m;
  m.press(0, MouseButton::left, 400, 300, kVp);
  m.move(0.01, 666.67, 300, kVp);  // 40 degrees
  m.sample(1);
  m.release(1, MouseButton::left);
  double min_x = 1;
  for (double t = 1; t <= 1.6; t += 0.001) min_x = std::min(min_x, glass_axis(m.sample(t).pose.orientation).x);
  EXPECT_GT(min_x, -1e-4);  // never leans past upright to the other side
  EXPECT_LT(tilt_angle(m.sample(1.6).pose.orientation), deg(0.5));  // within 10 time constants
}

TEST(GestureMouse, RateAndAccelerationMatchThePose) {
  MouseDriver m;
  m.press(0, MouseButton::left, 400, 300, kVp);
  m.press(0, MouseButton::right, 400, 300, kVp);  // swirl while holding the tilt
  for (int i = 1; i <= 50; ++i) m.move(0.01 * i, 400 + 100 * std::cos(0.3 * i), 300 + 100 * std::sin(0.3 * i), kVp);
  m.release(0.2, MouseButton::right);  // back to tilting, then drag
  m.move(0.25, 500, 200, kVp);
  const double h = 1e-4;
  for (double t = 0.05; t < 0.6; t += 0.037) {
    const MotionSample a = m.sample(t - h), b = m.sample(t), c = m.sample(t + h);
    const glm::dvec3 w = test::rate_between(a.pose.orientation, c.pose.orientation, 2 * h);
    EXPECT_NEAR(glm::length(w - b.angular_velocity), 0, 1e-3 * (1 + glm::length(w))) << "t = " << t;
    const glm::dvec3 acc = (a.pose.position - 2.0 * b.pose.position + c.pose.position) / (h * h);
    EXPECT_NEAR(glm::length(acc - b.linear_acceleration), 0, 1e-3 * (1 + glm::length(acc))) << "t = " << t;
  }
}

TEST(GestureMouse, AccelerationIsContinuousAcrossEvents) {
  MouseDriver m;
  m.press(0, MouseButton::right, 400, 300, kVp);
  m.move(0.1, 500, 300, kVp);  // a sudden jump of the target at t = 0.1
  m.sample(0.1 - 1e-7);
  const glm::dvec3 before = m.sample(0.1 - 1e-7).linear_acceleration;
  const glm::dvec3 after = m.sample(0.1 + 1e-7).linear_acceleration;
  EXPECT_GT(glm::length(m.sample(0.15).linear_acceleration), 0.05);  // it does accelerate
  EXPECT_LT(glm::length(after - before), 1e-3);
}

TEST(GestureMouse, RightDragSwirlsAndResultIgnoresSampleRate) {
  MouseDriver fast, slow;
  for (MouseDriver* m : {&fast, &slow}) {
    m->press(0, MouseButton::right, 400, 300, kVp);
    m->move(0.02, 460, 330, kVp);  // 0.1 / 0.05 of the height: 10 mm right, 5 mm towards the viewer
  }
  for (double t = 0; t < 0.5; t += 0.001) fast.sample(t);
  for (double t = 0; t < 0.5; t += 1.0 / 60) slow.sample(t);
  const MotionSample a = fast.sample(0.5), b = slow.sample(0.5);
  EXPECT_NEAR(glm::length(a.pose.position - b.pose.position), 0, 1e-12);
  EXPECT_NEAR(glm::length(a.linear_acceleration - b.linear_acceleration), 0, 1e-9);
  const MotionSample s = fast.sample(3);
  EXPECT_NEAR(s.pose.position.x, 0.01, 1e-9);
  EXPECT_NEAR(s.pose.position.z, 0.005, 1e-9);
  EXPECT_NEAR(tilt_angle(s.pose.orientation), 0, 1e-9);
  fast.release(3, MouseButton::right);
  EXPECT_NEAR(glm::length(fast.sample(6).pose.position), 0, 1e-9);
}

TEST(GestureMouse, BadEventsAreIgnored) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  MouseDriver m;
  m.press(0, MouseButton::left, 400, 300, kVp);
  m.move(0.01, 550, 300, kVp);
  m.move(0.02, nan, 300, kVp);
  m.move(0.03, 400, inf, kVp);
  m.move(nan, 0, 0, kVp);
  m.move(0.04, 0, 0, Viewport{800, 0});
  const MotionSample s = m.sample(2);
  EXPECT_NEAR(tilt_angle(s.pose.orientation), deg(22.5), deg(0.01));
  EXPECT_TRUE(std::isfinite(m.sample(nan).pose.orientation.w));
}

TEST(GestureTouch, OneFingerTiltsLikeTheMouse) {
  MouseDriver m;
  TouchDriver t;
  m.press(0, MouseButton::left, 100, 100, kVp);
  t.down(0, 7, 100, 100, kVp);
  m.move(0.05, 180, 40, kVp);
  t.move(0.05, 7, 180, 40, kVp);
  for (double s = 0; s < 0.5; s += 0.01) {
    const glm::dquat a = m.sample(s).pose.orientation, b = t.sample(s).pose.orientation;
    EXPECT_NEAR(std::abs(glm::dot(a, b)), 1, 1e-12);
  }
}

TEST(GestureTouch, TwistSpinsAboutTheGlassAxis) {
  TouchDriver t;
  t.down(0, 1, 300, 300, kVp);
  t.down(0, 2, 500, 300, kVp);
  // Finger 2 circles counter-clockwise (as seen) by 30 degrees about finger 1.
  for (int i = 1; i <= 10; ++i) t.move(0.01 * i, 2, 300 + 200 * std::cos(deg(3 * i)), 300 - 200 * std::sin(deg(3 * i)), kVp);
  const MotionSample s = t.sample(2);
  EXPECT_NEAR(tilt_angle(s.pose.orientation), 0, 1e-9);
  // Counter-clockwise seen from above: +30 degrees about +Y.
  EXPECT_NEAR(std::abs(glm::dot(s.pose.orientation, tilt_orientation(0, 0, deg(30)))), 1, 1e-9);
  // The midpoint moved too (by half of finger 2's motion): that swirls.
  EXPECT_LT(s.pose.position.x, 0);
  EXPECT_LT(s.pose.position.z, 0);
}

TEST(GestureTouch, AddingOrLiftingFingersDoesNotJump) {
  TouchDriver t;
  t.down(0, 1, 400, 300, kVp);
  t.move(0.01, 1, 520, 300, kVp);  // 18 degrees towards +X
  const glm::dquat tilted = t.sample(2).pose.orientation;
  EXPECT_NEAR(tilt_angle(tilted), deg(18), 1e-6);
  t.down(2, 2, 100, 500, kVp);  // a second finger far away
  t.move(2.01, 2, 110, 500, kVp);  // and a tiny drag of it
  t.up(2.02, 1);                   // the first lifts: finger 2 now tilts from where it is
  t.move(2.03, 2, 112, 500, kVp);  // 0.3 degrees more
  const MotionSample s = t.sample(4);
  EXPECT_NEAR(tilt_angle(s.pose.orientation), deg(18.3), deg(0.05));
  EXPECT_NEAR(glass_axis(s.pose.orientation).z, 0, 1e-3);
  for (double u = 2; u < 2.1; u += 0.005) EXPECT_LT(glm::length(t.sample(u).angular_velocity), 0.2);
  t.up(4, 2);
  EXPECT_LT(tilt_angle(t.sample(6).pose.orientation), 1e-9);
}

}  // namespace
}  // namespace draught
