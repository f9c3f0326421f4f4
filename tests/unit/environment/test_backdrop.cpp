// The backdrop: the sweep is one continuous surface (floor, quarter cylinder, wall) met
// once by every ray from the scene that goes down or back, with its normal towards the
// scene; the checker floor is the plane y = 0 with its two albedos.
#include "core/environment/backdrop.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught {
namespace {

BackdropSurface sweep() {
  EnvParams e;
  e.backdrop = int(Backdrop::Sweep);
  e.sweep_distance = 0.3f;
  e.sweep_radius = 0.2f;
  return backdrop_surface(e, {0.0, 0.07, 0.1});  // z_curve = -0.2, the wall at z = -0.4
}

TEST(Backdrop, TheSweepIsFloorCurveAndWall) {
  const BackdropSurface b = sweep();
  double t;
  glm::dvec3 n;
  // Straight down onto the floor.
  ASSERT_TRUE(b.intersect({0.1, 0.5, 0.0}, {0, -1, 0}, 0, t, n));
  EXPECT_NEAR(t, 0.5, 1e-12);
  EXPECT_EQ(n, glm::dvec3(0, 1, 0));
  // Straight back at the wall, above the curve.
  ASSERT_TRUE(b.intersect({0.0, 0.3, 0.5}, {0, 0, -1}, 0, t, n));
  EXPECT_NEAR(t, 0.5 - (b.z_curve - b.radius), 1e-12);
  EXPECT_NEAR(t, 0.9, 1e-6);
  EXPECT_EQ(n, glm::dvec3(0, 0, 1));
  // Back at the curve's height: 45 degrees into the quarter.
  const double s = std::sqrt(0.5);
  const double r = b.radius, zc = b.z_curve;
  ASSERT_TRUE(b.intersect({0.0, r - r * s, 0.5}, {0, 0, -1}, 0, t, n));
  EXPECT_NEAR(0.5 - t, zc - r * s, 1e-12);
  EXPECT_NEAR(n.y, s, 1e-9);
  EXPECT_NEAR(n.z, s, 1e-9);
  // Up and forward: nothing.
  EXPECT_FALSE(b.intersect({0.0, 0.1, 0.0}, glm::normalize(glm::dvec3(0, 1, 1)), 0, t, n));
}

TEST(Backdrop, EveryRayDownOrBackMeetsTheSweepOnceOnItsSurface) {
  const BackdropSurface b = sweep();
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const double az = 0.0031 * i * 7, el = -1.4 + 2.6 * ((i * 37) % 1000) / 1000.0;
    const glm::dvec3 d(std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az));
    if (d.y >= 0 && d.z >= 0) continue;
    const glm::dvec3 o(0.05, 0.12, 0.25);
    double t;
    glm::dvec3 n;
    ASSERT_TRUE(b.intersect(o, d, 0, t, n)) << d.x << " " << d.y << " " << d.z;
    ++hits;
    const glm::dvec3 p = o + t * d;
    // On the floor, on the curve or on the wall.
    const double r = b.radius, zc = b.z_curve, ry = p.y - r, rz = p.z - zc;
    const bool on_floor = std::fabs(p.y) < 1e-9 && p.z >= zc - 1e-9;
    const bool on_curve = std::fabs(std::hypot(ry, rz) - r) < 1e-9 && ry <= 1e-9 && rz <= 1e-9;
    const bool on_wall = std::fabs(p.z - (zc - r)) < 1e-9 && p.y >= r - 1e-9;
    EXPECT_TRUE(on_floor || on_curve || on_wall) << p.x << " " << p.y << " " << p.z;
    EXPECT_LT(glm::dot(n, d), 0.0);  // it faces the ray
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
  }
  EXPECT_GT(hits, 500);
}

TEST(Backdrop, TheCheckerFloorIsEndlessWithTwoAlbedos) {
  EnvParams e;
  e.backdrop = int(Backdrop::Checker);
  e.checker_size = 0.1f;
  const BackdropSurface b = backdrop_surface(e, {0, 0, 0});
  double t;
  glm::dvec3 n;
  ASSERT_TRUE(b.intersect({0, 1, 0}, glm::normalize(glm::dvec3(0, -1, -20)), 0, t, n));
  EXPECT_NEAR((glm::dvec3(0, 1, 0) + t * glm::normalize(glm::dvec3(0, -1, -20))).z, -20, 1e-9);
  EXPECT_NE(b.albedo({0.05, 0, 0.05}), b.albedo({0.15, 0, 0.05}));
  EXPECT_EQ(b.albedo({0.05, 0, 0.05}), b.albedo({0.15, 0, 0.15}));
  e.floor = false;
  EXPECT_FALSE(backdrop_surface(e, {0, 0, 0}).intersect({0, 1, 0}, {0, -1, 0}, 0, t, n));
}

}  // namespace
}  // namespace draught
