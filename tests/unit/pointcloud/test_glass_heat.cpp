// Glass cooling: Newton's law in closed form, radiation on top of it, the named heats.
#include "core/pointcloud/glass_heat.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace draught {
namespace {

TEST(GlassHeat, NewtonCoolingClosedForm) {
  EXPECT_EQ(cooled_temperature(1373, 293, 0, 10), 1373);
  EXPECT_NEAR(cooled_temperature(1373, 293, 10, 10), 293 + 1080 / std::exp(1.0), 1e-9);
  EXPECT_NEAR(cooled_temperature(1373, 293, 1e4, 10), 293, 1e-9);
  EXPECT_EQ(cooled_temperature(1373, 293, 5, 0), 1373);  // no time constant: no cooling
  double last = 1373;
  for (double s = 0.5; s < 60; s += 0.5) {
    const double t = cooled_temperature(1373, 293, s, 10);
    EXPECT_LT(t, last);
    last = t;
  }
}

TEST(GlassHeat, RadiationWithoutEmissivityIsNewton) {
  GlassCooling g;
  g.emissivity = 0;
  const double tau = g.density * g.heat_capacity * g.thickness / g.convection;
  for (double s : {1.0, 30.0, 600.0})
    EXPECT_NEAR(cooled_glass_temperature(g, 1373, 293, s), cooled_temperature(1373, 293, s, tau), 1e-6);
}

TEST(GlassHeat, RadiationDominatesWhenHot) {
  GlassCooling g;
  const double ta = 293.15;
  // At 1100 C radiation carries far more than convection...
  GlassCooling still = g;
  still.convection = 0;
  EXPECT_GT(glass_cooling_rate(still, 1373.15, ta) / glass_cooling_rate(g, 1373.15, ta), 0.9);
  // ...so the hot gob cools much faster than a Newtonian one fitted near room temperature.
  const double tau = g.density * g.heat_capacity * g.thickness / g.convection;
  EXPECT_LT(cooled_glass_temperature(g, 1373.15, ta, 60), cooled_temperature(1373.15, ta, 60, tau) - 100);
  // Monotonic towards ambient, never past it, and converged in its step count: halving
  // the time in two calls gives the same answer.
  const double one = cooled_glass_temperature(g, 1373.15, ta, 120);
  const double two = cooled_glass_temperature(g, cooled_glass_temperature(g, 1373.15, ta, 60), ta, 60);
  EXPECT_NEAR(one, two, 1e-6);
  EXPECT_GT(cooled_glass_temperature(g, 1373.15, ta, 1e6), ta - 1e-9);
  EXPECT_LT(cooled_glass_temperature(g, 1373.15, ta, 1e6), ta + 1);
  // A 4 cm gob takes minutes to lose its glow (below ~800 K), not seconds: ~6.5 min.
  EXPECT_GT(cooled_glass_temperature(g, 1373.15, ta, 30), 1200);
  EXPECT_GT(cooled_glass_temperature(g, 1373.15, ta, 300), 800);
  EXPECT_LT(cooled_glass_temperature(g, 1373.15, ta, 420), 800);
}

TEST(GlassHeat, NamedHeats) {
  EXPECT_NEAR(*glass_heat("gob"), 1373.15, 1e-9);
  EXPECT_NEAR(*glass_heat("cooling"), 973.15, 1e-9);
  EXPECT_NEAR(*glass_heat("cooled"), 293.15, 1e-9);
  EXPECT_FALSE(glass_heat("lukewarm").has_value());
  double last = 1e9;
  for (const GlassHeat& h : kGlassHeats) {  // listed hottest first
    EXPECT_LT(h.kelvin, last) << h.name;
    last = h.kelvin;
  }
}

}  // namespace
}  // namespace draught
