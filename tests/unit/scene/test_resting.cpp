// A tipped glass rests on the floor: the lowest point of its geometry, found here by
// brute force over the outer surface, is at floor height (y = 0), whatever turned it.
#include "core/scene/motion.hpp"
#include "core/sim/simulation.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace draught {
namespace {

// The lowest world height of the glass's outer surface (walls and foot, rim bead), by
// sampling: 720 directions round the axis, rings at and between the profile's knots.
double lowest_point(const Vessel& v, const Pose& pose) {
  double lowest = 1e9;
  auto visit = [&](double r, double y) {
    for (int j = 0; j < 720; ++j) {
      const double a = 2 * std::numbers::pi * j / 720;
      lowest = std::min(lowest, (pose.orientation * glm::dvec3(r * std::cos(a), y, r * std::sin(a)) + pose.position).y);
    }
  };
  // The wall is straight between knots, so its lowest point is at a knot; the quarters
  // between them are sampled too, in case it were not.
  for (double y = 0; y <= v.height + 1e-12; y += v.dy / 4) visit(v.outer_radius(std::min(y, v.height)), y);
  for (int k = 0; k < 72; ++k) {  // the bead's cross-section
    const double b = 2 * std::numbers::pi * k / 72;
    visit(v.rim_major + v.rim_minor * std::cos(b), v.height + v.rim_minor * std::sin(b));
  }
  return lowest;
}

TEST(Resting, ATippedGlassTouchesTheFloorWithItsLowestPoint) {
  for (const std::string glass : {"pint", "wine", "flute", "nonic", "weizen"}) {
    const Vessel v = test::preset_vessel(glass);
    for (double tilt : {0.0, 5.0, 14.0, 40.0, 75.0, 95.0, 135.0})
      for (double toward : {0.0, 130.0}) {
        const glm::dquat q = tilt_orientation(tilt * kDegree, toward * kDegree, 0.3);
        // Turned about the middle of its foot (as the mouse and the gyro turn it), and
        // tipped on the rim of its foot (as a timeline tips it): both come to rest on it.
        for (Pose p : {Pose{q, {0.1, 0.0, -0.05}}, tipped_on_floor(q, v.r_outer.front())}) {
          const double low = lowest_point(v, resting_on_floor(p, v));
          EXPECT_GT(low, -2e-5) << glass << " tilted " << tilt << " towards " << toward << ": sinks into the floor";
          EXPECT_LT(low, 2e-5) << glass << " tilted " << tilt << " towards " << toward << ": floats above the floor";
        }
      }
  }
}

TEST(Resting, AGlassHeldAboveTheFloorStaysThere) {
  const Vessel v = test::preset_vessel("pint");
  const Pose held{tilt_orientation(20 * kDegree, 0.0), {0, 0.05, 0}};
  EXPECT_EQ(resting_on_floor(held, v).position, held.position);
}

TEST(Resting, TheSimulationRestsWhatADriverTurnsAboutTheFoot) {
  // A driver that turns the glass about the middle of its foot at the floor would push
  // half the foot through it; the simulation's pose stands on the foot's edge instead.
  Simulation sim(resolve_scene({"lager", "pint", {}, {}}));
  MotionSample m;
  m.pose.orientation = tilt_orientation(25 * kDegree, 0.0);
  for (int i = 0; i < 10; ++i) sim.step(m);
  const Pose p = sim.frame().pose;
  EXPECT_NEAR(lowest_point(sim.frame().vessel, p), 0.0, 2e-5);
  EXPECT_GT(p.position.y, 0.0);
  EXPECT_EQ(p.orientation, m.pose.orientation);
}

}  // namespace
}  // namespace draught
