// Condensation on a cold glass (core/condensation): beads stay on the wall's band, merge
// conserving water, run down leaving a clear trail, drain at the foot; everything is
// deterministic per seed; the bead grid finds every bead and draws it as a cap.
#include "core/condensation/condensation.hpp"
#include "core/condensation/wall_grid.hpp"
#include "core/params/params.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {
namespace {

Vessel pint() { return build_vessel(default_params().glass); }

CondensationParams cold(int seed = 1) {
  CondensationParams c;
  c.enabled = true;
  c.seed = seed;
  return c;
}

// Only what a test places: no seeded beads, no growth, no fog coming back.
CondensationParams still() {
  CondensationParams c = cold();
  c.count = 0;
  c.growth = 0;
  c.age = 0;
  return c;
}

double total_water(const Condensation& c) { return c.bead_water() + c.shed_water() + c.drained_water(); }

TEST(Condensation, BeadsStayOnTheWallsBand) {
  const Vessel v = pint();
  Condensation c(cold(), v, 0.12);
  const CondensationBand b = c.state().band;
  EXPECT_NEAR(b.y1, 0.12 + 0.004, 1e-9);
  EXPECT_GT(c.state().beads.size(), 500u);
  for (int s = 0; s < 300; ++s) {
    c.step();
    for (const Bead& bead : c.state().beads) {
      ASSERT_GE(bead.y, b.y0 - 1e-12);
      ASSERT_LE(bead.y, b.y1 + 1e-12);
      ASSERT_GE(bead.angle, -kPi);
      ASSERT_LT(bead.angle, kPi);
      ASSERT_GT(bead.radius, 0.0);
    }
  }
}

TEST(Condensation, SeededBeadsDoNotOverlapAndMergingKeepsThemApart) {
  const Vessel v = pint();
  Condensation c(cold(), v, 0.12);
  for (int round = 0; round < 2; ++round) {
    const auto& beads = c.state().beads;
    int overlapping = 0;
    for (size_t i = 0; i < beads.size(); ++i)
      for (size_t j = i + 1; j < beads.size(); ++j) {
        if (std::fabs(beads[j].y - beads[i].y) >= beads[i].radius + beads[j].radius) continue;
        const double r = v.outer_radius(0.5 * (beads[i].y + beads[j].y));
        double da = beads[j].angle - beads[i].angle;
        da -= 2 * kPi * std::floor(da / (2 * kPi) + 0.5);
        const double d = std::hypot(r * da, beads[j].y - beads[i].y);
        overlapping += d < 0.999 * (beads[i].radius + beads[j].radius);
      }
    EXPECT_EQ(overlapping, 0);
    for (int s = 0; s < 15; ++s) c.step();  // to the next full merge
  }
}

TEST(Condensation, TouchingBeadsMergeConservingWater) {
  Condensation c(still(), pint(), 0.12);
  c.place_bead({0.3, 0.06, 0.0012, false});
  c.place_bead({0.3 + 0.0015 / pint().outer_radius(0.06), 0.0605, 0.0009, false});  // 1.5 mm apart: they touch
  const double before = total_water(c);
  c.step();
  ASSERT_EQ(c.state().beads.size(), 1u);
  const Bead& b = c.state().beads[0];
  EXPECT_NEAR(b.radius, std::cbrt(std::pow(0.0012, 3) + std::pow(0.0009, 3)), 1e-12);
  EXPECT_NEAR(total_water(c), before, 1e-12 * before);
  EXPECT_GT(b.angle, 0.3);  // the centre of mass lies between them, nearer the bigger
  EXPECT_LT(b.y, 0.06025);
}

TEST(Condensation, AHeavyBeadRunsDownTakingTheBeadsInItsWayAndClearingTheFog) {
  CondensationParams p = still();
  Condensation c(p, pint(), 0.12);
  const double slide = p.slide_radius;
  c.place_bead({0.0, 0.10, 1.3 * slide, false});
  c.place_bead({0.0, 0.07, 0.0008, false});  // in its way
  c.place_bead({1.0, 0.07, 0.0008, false});  // not
  const double before = total_water(c);
  const float fog_before = fog_at(fog_texels(c.state()), c.state().band, {0.0f, 0.09f, float(pint().outer_radius(0.09))});
  for (int s = 0; s < 45; ++s) c.step();  // 1.5 s
  const auto& beads = c.state().beads;
  ASSERT_EQ(beads.size(), 2u) << "the runner took the bead in its way";
  const Bead& runner = beads[0].radius > beads[1].radius ? beads[0] : beads[1];
  EXPECT_LT(runner.y, 0.07);
  EXPECT_TRUE(runner.sliding);
  EXPECT_GT(c.shed_water(), 0.0);
  EXPECT_NEAR(total_water(c), before, 1e-12 * before);
  const float fog_after = fog_at(fog_texels(c.state()), c.state().band, {0.0f, 0.09f, float(pint().outer_radius(0.09))});
  EXPECT_GT(fog_before, 0.2f);
  EXPECT_LT(fog_after, 0.02f) << "the trail is clear";
  // It keeps running to the band's foot, where it drains.
  for (int s = 0; s < 300; ++s) c.step();
  EXPECT_EQ(c.state().beads.size(), 1u);
  EXPECT_GT(c.drained_water(), 0.0);
  EXPECT_NEAR(total_water(c), before, 1e-12 * before);
}

TEST(Condensation, ASmallBeadStaysPut) {
  Condensation c(still(), pint(), 0.12);
  c.place_bead({-1.0, 0.08, 0.001, false});
  for (int s = 0; s < 90; ++s) c.step();
  ASSERT_EQ(c.state().beads.size(), 1u);
  EXPECT_EQ(c.state().beads[0].y, 0.08);
  EXPECT_FALSE(c.state().beads[0].sliding);
}

TEST(Condensation, DeterministicPerSeed) {
  Condensation a(cold(7), pint(), 0.12), b(cold(7), pint(), 0.12), other(cold(8), pint(), 0.12);
  a.advance_to(2.0);
  b.advance_to(2.0);
  other.advance_to(2.0);
  ASSERT_EQ(a.state().beads.size(), b.state().beads.size());
  for (size_t i = 0; i < a.state().beads.size(); ++i) {
    EXPECT_EQ(a.state().beads[i].angle, b.state().beads[i].angle);
    EXPECT_EQ(a.state().beads[i].y, b.state().beads[i].y);
    EXPECT_EQ(a.state().beads[i].radius, b.state().beads[i].radius);
  }
  EXPECT_EQ(a.state().fog, b.state().fog);
  EXPECT_NE(a.state().beads.size() == other.state().beads.size() && a.state().beads[0].y == other.state().beads[0].y, true);
}

TEST(Condensation, GrowthGrowsBeadsAndBringsNewOnes) {
  CondensationParams p = cold();
  p.age = 0;
  p.count = 300;
  Condensation c(p, pint(), 0.12);
  const double water = c.bead_water();
  c.advance_to(5.0);
  EXPECT_GT(c.bead_water(), water);
}

TEST(Condensation, AHandPrintIsClear) {
  CondensationParams p = cold();
  p.hand = true;
  p.hand_angle = 0;
  p.hand_height = 0.07f;
  p.age = 0;  // (later, beads running down from above cross the print, as on a real glass)
  Condensation c(p, pint(), 0.12);
  EXPECT_GT(c.hand_print(0.0, 0.07), 0.99);
  EXPECT_LT(c.hand_print(kPi, 0.07), 0.01);
  const std::vector<std::uint8_t> fog = fog_texels(c.state());
  EXPECT_EQ(fog_at(fog, c.state().band, {0.0f, 0.07f, float(pint().outer_radius(0.07))}), 0.0f);
  EXPECT_GT(fog_at(fog, c.state().band, {0.0f, 0.07f, -float(pint().outer_radius(0.07))}), 0.2f);
  for (const Bead& b : c.state().beads) EXPECT_LT(c.hand_print(b.angle, b.y), 0.5) << b.angle << " " << b.y;
}

TEST(Condensation, AnEmptyGlassStaysDry) {
  const Vessel v = pint();
  Condensation c(cold(), v, v.base - 0.02);
  EXPECT_TRUE(c.state().band.empty());
  EXPECT_TRUE(c.state().beads.empty());
  c.advance_to(1.0);
  EXPECT_TRUE(c.state().beads.empty());
}

// A fog without beads (count 0, a slider's end): it ages like any other (the merge's grid
// was once sized to a bead of no size, tens of millions of cells a step, and a glass took a
// minute to age), and the one bead placed on it later stays as it is.
TEST(Condensation, AFogWithoutBeadsAgesAndKeepsItsFog) {
  CondensationParams p = cold();
  p.count = 0;
  Condensation c(p, pint(), 0.12);
  c.advance_to(5.0);
  EXPECT_TRUE(c.state().beads.empty());
  float most = 0;
  for (float f : c.state().fog) most = std::max(most, f);
  EXPECT_GT(most, 0.2f);
  c.place_bead({0.5, 0.07, 0.0008, false});
  c.advance_to(6.0);
  ASSERT_EQ(c.state().beads.size(), 1u);
  EXPECT_GT(c.state().beads[0].radius, 0.0008);  // it grew
}

TEST(CondensationGrid, FindsEveryBeadAndDrawsItAsACap) {
  const Vessel v = pint();
  Condensation c(cold(), v, 0.12);
  const CondensationState& s = c.state();
  const std::vector<glm::vec4> grid = bead_grid(s, v);
  int missed = 0;
  for (const Bead& b : s.beads) {
    const float r = float(v.outer_radius(b.y));
    const glm::vec3 p(r * std::sin(float(b.angle)), float(b.y), r * std::cos(float(b.angle)));
    const glm::vec3 n = glm::normalize(glm::vec3(p.x, 0.0f, p.z));  // (the pint's wall is nearly upright)
    const BeadSample at = bead_at(grid, s.band, s.contact_angle, p, n);
    missed += !at.found;
    if (at.found) {
      EXPECT_GT(glm::dot(at.normal, n), 0.9999f);  // the cap's top faces out
      EXPECT_EQ(at.clear, 0.0f);
    }
  }
  EXPECT_LE(missed, int(s.beads.size()) / 200) << "beads lost to full cells";
}

TEST(CondensationGrid, ACapsEdgeMeetsTheWallAtTheContactAngle) {
  Condensation c(still(), pint(), 0.12);
  const Vessel v = pint();
  c.place_bead({0.0, 0.06, 0.002, false});
  const CondensationState& s = c.state();
  const std::vector<glm::vec4> grid = bead_grid(s, v);
  const float r = float(v.outer_radius(0.06));
  // Just inside the edge, above the centre: the normal leans up by nearly the contact angle.
  const glm::vec3 wall = glm::normalize(glm::vec3(0.0f, -float(v.outer_radius(0.061) - v.outer_radius(0.059)) / 0.002f, 1.0f));
  const BeadSample at = bead_at(grid, s.band, s.contact_angle, {0.0f, 0.06f + 0.001999f * wall.z, r}, wall);
  ASSERT_TRUE(at.found);
  EXPECT_NEAR(std::acos(glm::dot(at.normal, wall)), s.contact_angle, 0.02);
  const BeadSample outside = bead_at(grid, s.band, s.contact_angle, {0.0f, 0.06f + 0.0026f, r}, wall);
  EXPECT_FALSE(outside.found);
  EXPECT_GT(outside.clear, 0.0f);
  EXPECT_LT(outside.clear, 1.0f);
}

}  // namespace
}  // namespace draught
