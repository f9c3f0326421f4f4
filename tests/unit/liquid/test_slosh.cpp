// The slosh model on its own: the first mode's frequency, free oscillation, decay to an
// exact rest, the limits it keeps, and the wave shapes (which must move no volume).
#include "core/liquid/slosh.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace draught {
namespace {

constexpr double kG = 9.80665;
constexpr double kDt = 1.0 / 240.0;

LiquidParams liquid(float damping = 0.06f) {
  LiquidParams p{};
  p.slosh_stiffness = 1.0f;
  p.slosh_damping = damping;
  p.wave_amplitude = 1.0f;
  p.wave_speed = 1.0f;
  return p;
}

TEST(SloshFrequency, MatchesTheCylinderFormula) {
  // omega^2 = g xi / R tanh(xi H / R), xi = 1.8412; values worked out by hand (Python).
  EXPECT_NEAR(slosh_frequency(0.04, 0.1), 21.244044716, 1e-6);
  EXPECT_NEAR(slosh_frequency(0.05, 0.02), 15.047499959, 1e-6);
  EXPECT_NEAR(slosh_frequency(0.03, 0.2), 24.532973715, 1e-6);
  // Deep: tanh -> 1, omega^2 = g xi / R. Shallow: tanh x ~ x, omega^2 = g xi^2 H / R^2.
  EXPECT_NEAR(slosh_frequency(0.05, 1.0), std::sqrt(kG * 1.8412 / 0.05), 1e-9);
  EXPECT_NEAR(slosh_frequency(0.05, 1e-3), 1.8412 / 0.05 * std::sqrt(kG * 1e-3), 1e-3);
  // Other modes: the root is a parameter (3.8317, first root of J1: the ring).
  EXPECT_NEAR(slosh_frequency(0.04, 0.1, 3.8317), std::sqrt(kG * 3.8317 / 0.04 * std::tanh(3.8317 * 2.5)), 1e-9);
}

TEST(SloshFrequency, StaysFiniteForDegenerateGlasses) {
  for (double r : {0.0, -1.0, 1e-9})
    for (double h : {0.0, -1.0, 1e-9}) EXPECT_TRUE(std::isfinite(slosh_frequency(r, h)) && slosh_frequency(r, h) > 0);
}

TEST(SloshModel, FreeOscillationRingsAtTheNaturalFrequency) {
  // Released from a tilt with no forcing: the slope oscillates at the first mode's damped
  // frequency omega sqrt(1 - zeta^2) (semi-implicit Euler adds ~(omega dt)^2 / 24).
  SloshEnvironment e;
  e.radius = 0.04, e.depth = 0.1;
  const LiquidParams p = liquid(0.01f);
  SloshState s;
  s.slope = {0.1, 0.0};
  std::vector<double> crossings;
  double prev = s.slope.x;
  for (int i = 1; i < 240 * 3; ++i) {
    step_slosh(s, p, e, kDt);
    if ((prev < 0) != (s.slope.x < 0)) crossings.push_back((i - 1 + prev / (prev - s.slope.x)) * kDt);
    prev = s.slope.x;
  }
  ASSERT_GE(crossings.size(), 10u);
  const double period = 2 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  const double w = slosh_frequency(0.04, 0.1);
  EXPECT_NEAR(2 * kPi / period, w * std::sqrt(1 - 0.01 * 0.01), 0.01 * w);
}

TEST(SloshModel, DecaysAndSnapsToAnExactRest) {
  SloshEnvironment e;
  e.radius = 0.04, e.depth = 0.08;
  e.level_slope = {0.05, -0.02};  // resting under a steady acceleration
  const LiquidParams p = liquid();
  SloshState s;
  s.slope = {0.3, 0.2};
  s.ring = 0.004, s.cross = {0.003, -0.002};
  double window = 0, last = 1e300;
  int steps = 0;
  for (; steps < 240 * 30 && !at_rest(s); ++steps) {
    step_slosh(s, p, e, kDt);
    window += slosh_energy(s, p, e);
    if (steps % 60 == 59) {  // 0.25 s windows: the mean falls
      EXPECT_LT(window, last) << "t = " << steps * kDt;
      last = window, window = 0;
    }
  }
  EXPECT_TRUE(at_rest(s)) << "still moving after 30 s";
  EXPECT_LT(steps * kDt, 15.0);
  EXPECT_EQ(s.slope, e.level_slope) << "rests exactly at the level";
  EXPECT_EQ(slosh_energy(s, p, e), 0.0);
  // And stays there: no jitter from further steps.
  for (int i = 0; i < 240; ++i) step_slosh(s, p, e, kDt);
  EXPECT_TRUE(at_rest(s));
  EXPECT_EQ(s.slope, e.level_slope);
}

TEST(SloshModel, KeepsItsLimitsUnderViolentForcing) {
  SloshEnvironment e;
  e.radius = 0.04, e.depth = 0.1, e.max_slope = 0.8, e.max_wave = 0.003;
  const LiquidParams p = liquid(0.005f);
  SloshState s;
  for (int i = 0; i < 2400; ++i) {
    const double sgn = (i / 7) % 2 ? 1.0 : -1.0;  // a square wave at ~17 Hz
    e.level_slope = {sgn * 0.8, 0.3 * sgn};
    e.level_rate = {sgn * 1e3, -sgn * 1e3};
    step_slosh(s, p, e, kDt);
    ASSERT_LE(glm::length(s.slope), e.max_slope + 1e-12);
    ASSERT_LE(std::abs(s.ring), e.max_wave);
    ASSERT_LE(std::abs(s.cross.x), e.max_wave);
    ASSERT_LE(std::abs(s.cross.y), e.max_wave);
    ASSERT_TRUE(std::isfinite(slosh_energy(s, p, e)));
  }
}

TEST(SloshWaves, MoveNoVolumeAndAreFlatAtTheWall) {
  // Midpoint integral over the disk of radius R: each shape has zero mean.
  const double R = 0.04;
  for (SurfaceWaves w : {SurfaceWaves{0.003, {0, 0}, R}, SurfaceWaves{0, {0.002, 0}, R}, SurfaceWaves{0, {0, -0.002}, R}}) {
    const int n = 800;
    const double h = 2 * R / n;
    double sum = 0, peak = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double x = -R + (i + 0.5) * h, z = -R + (j + 0.5) * h;
        if (x * x + z * z > R * R) continue;
        sum += w.height(x, z) * h * h;
        peak = std::max(peak, std::abs(w.height(x, z)));
      }
    EXPECT_GT(peak, 1e-3);
    EXPECT_NEAR(sum / (kPi * R * R), 0.0, 1e-3 * peak) << "mean height over the disk";
  }
  // The ring is flat at the wall (radial slope 0 at r = R).
  const SurfaceWaves ring{0.003, {0, 0}, R};
  const glm::dvec2 g = ring.gradient(R * 0.6, R * 0.8);
  EXPECT_NEAR(g.x * 0.6 + g.y * 0.8, 0.0, 1e-12);
}

TEST(SloshWaves, GradientIsTheHeightsDerivative) {
  // (0.033, 0.03) lies beyond 1.25 radii, where each shape is held at its value on that
  // circle: the height still varies with the angle there, so the gradient must too.
  const SurfaceWaves w{0.002, {0.0015, -0.001}, 0.035};
  const double h = 1e-7;
  for (double x : {-0.03, -0.01, 0.0, 0.012, 0.033})
    for (double z : {-0.02, 0.0, 0.005, 0.03}) {
      const glm::dvec2 g = w.gradient(x, z);
      EXPECT_NEAR(g.x, (w.height(x + h, z) - w.height(x - h, z)) / (2 * h), 1e-6) << x << ", " << z;
      EXPECT_NEAR(g.y, (w.height(x, z + h) - w.height(x, z - h)) / (2 * h), 1e-6) << x << ", " << z;
    }
}

// Where a pour's stream plunges in: the surface dips by the dimple's depth under it, rises
// in a low ring round it, moves no volume (the hollow and the ring cancel over the plane),
// and its gradient is its height's derivative, with waves on it too.
TEST(SloshWaves, APoursDimpleDipsUnderTheStreamAndMovesNoVolume) {
  SurfaceWaves w{0.0, {0, 0}, 0.04};
  w.dimple_xz = {0.004, -0.003};
  w.dimple_radius = 0.008;
  w.dimple_depth = 0.003;
  EXPECT_FALSE(w.flat());
  EXPECT_NEAR(w.height(0.004, -0.003), -0.003, 1e-15);
  EXPECT_EQ(w.gradient(0.004, -0.003), glm::dvec2(0.0));
  // The ring's crest, sqrt(2) radii out: 0.135 of the depth above the plane.
  EXPECT_NEAR(w.height(0.004 + std::sqrt(2.0) * 0.008, -0.003), 0.003 * std::exp(-2.0), 1e-12);
  const int n = 1200;
  const double R = 0.06, h = 2 * R / n;  // (the dimple is 7 radii inside: its tail is below 1e-20)
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) sum += w.height(-R + (i + 0.5) * h + 0.004, -R + (j + 0.5) * h - 0.003) * h * h;
  EXPECT_NEAR(sum, 0.0, 1e-4 * 0.003 * kPi * 0.008 * 0.008) << "the hollow and its ring move no volume";
  SurfaceWaves both = w;
  both.ring = 0.001;
  both.cross = {0.0005, -0.0007};
  const double d = 1e-7;
  for (double x : {-0.01, 0.0, 0.006, 0.012})
    for (double z : {-0.01, -0.002, 0.004}) {
      const glm::dvec2 g = both.gradient(x, z);
      EXPECT_NEAR(g.x, (both.height(x + d, z) - both.height(x - d, z)) / (2 * d), 1e-6) << x << ", " << z;
      EXPECT_NEAR(g.y, (both.height(x, z + d) - both.height(x, z - d)) / (2 * d), 1e-6) << x << ", " << z;
    }
}

}  // namespace
}  // namespace draught
