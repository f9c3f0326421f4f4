// The pour seen (issue 14): a stream falls from above into the emptied glass, the level
// rises as its volume arrives (the stream's and the glass's volumes add up to what left
// the spout at every step), the head builds from the first splash, and the stream is gone
// once the last of it has landed; what spills over the rim leaves as a stream of the
// same volume. The pour action's duration, its default and the instant fill.
#include "core/sim/simulation.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/scene/motion.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace draught {
namespace {

constexpr double kPourDt = Simulation::kStep;

Params pour_lager_in_pint(float fill) {
  Params p = resolve_scene({"lager", "pint", {}, {}});
  p.liquid.fill = fill;
  return p;
}

TEST(Pour, TheLevelRisesAsTheStreamArrivesAndTheVolumeAddsUp) {
  const Params p = pour_lager_in_pint(0.8f);
  Simulation sim(p);
  const double cavity = sim.vessel().cavity_volume(), seconds = 2.0;
  sim.pour_over(seconds);
  EXPECT_EQ(sim.fraction(), 0.0) << "a fresh pour starts with an empty glass";
  const double flow = double(p.liquid.fill) * cavity / seconds;
  double prev = 0, first_drink = -1;
  bool stream_seen = false;
  for (int i = 1; i <= int(4.0 / kPourDt); ++i) {
    sim.step(MotionSample{});
    const double t = i * kPourDt, poured = flow * std::min(t, seconds);
    ASSERT_GE(sim.fraction(), prev - 1e-15) << "the level never falls during a pour, t = " << t;
    prev = sim.fraction();
    if (first_drink < 0 && sim.fraction() > 0) first_drink = t;
    const std::vector<CloudFrame> streams = sim.streams();
    if (t > 0.1 && t < seconds) {
      ASSERT_EQ(streams.size(), 1u) << "the stream is in the air while the tap runs, t = " << t;
      stream_seen = true;
      EXPECT_EQ(streams[0].material, int(CloudMaterial::Drink));
      EXPECT_EQ(streams[0].glow, 0.0f);
      EXPECT_GT(streams[0].points->size(), 20u);
      // Every point is above the drink's surface in the world (the glass stands at the origin).
      const double surface = sim.fraction() > 0 ? sim.vessel().fill_height(sim.fraction()) : sim.vessel().base;
      for (const glm::vec3& q : streams[0].points->position) ASSERT_GT(q.y, surface - 0.01);
    }
    // What left the spout is in the glass or still falling.
    ASSERT_LE(sim.fraction() * cavity, poured * (1 + 1e-9) + 1e-15);
    if (t > seconds + 0.5) {
      ASSERT_TRUE(streams.empty()) << "the last of the stream has landed, t = " << t;
    }
  }
  EXPECT_TRUE(stream_seen);
  EXPECT_NEAR(sim.fraction(), double(p.liquid.fill), 1e-12) << "all that was poured is in the glass";
  // The stream falls about a third of a metre: the first drink lands after ~0.2 s.
  EXPECT_GT(first_drink, 0.1);
  EXPECT_LT(first_drink, 0.4);
  EXPECT_GT(sim.foam().thickness(), 0.0) << "the head built from the splash";
  EXPECT_FALSE(sim.pouring());
}

// The stream pushes the head aside where it plunges in: a dimple under the stream while
// it lands, which the foam fills again once the last of it has landed.
TEST(Pour, TheStreamPlungesThroughTheHeadInADimpleThatClosesAfterIt) {
  Simulation sim(pour_lager_in_pint(0.8f));
  const double seconds = 2.0;
  sim.pour_over(seconds);
  for (int i = 1; i <= int(1.5 / kPourDt); ++i) sim.step(MotionSample{});
  ASSERT_TRUE(sim.pouring());
  const FoamFrame mid = sim.frame().foam;
  EXPECT_NEAR(mid.crater_depth, FoamFrame::kMaxCraterDepth, 0.01) << "open while the stream lands";
  // Under the stream: its lowest points over the dimple's middle (the glass stands at
  // the origin, upright).
  const std::vector<CloudFrame> streams = sim.streams();
  ASSERT_EQ(streams.size(), 1u);
  glm::vec3 lowest(0.0f, 1e9f, 0.0f);
  for (const glm::vec3& q : streams[0].points->position)
    if (q.y < lowest.y) lowest = q;
  EXPECT_LT(glm::length(glm::dvec2(lowest.x, lowest.z) - mid.crater_xz), 0.5 * mid.crater_radius);
  EXPECT_GT(mid.crater_radius, 0.003);
  EXPECT_LT(mid.crater_radius, 0.03);
  const double r = sim.vessel().inner_radius(sim.vessel().fill_height(sim.fraction()));
  EXPECT_LT(mid.thickness_at(mid.crater_xz.x, mid.crater_xz.y, r), 0.2 * mid.thickness_at(-0.8 * r, 0.0, r));
  // The drink's surface dips there too, about as deep as the stream is thick, and the
  // stream goes down into it.
  const SurfaceWaves& waves = sim.frame().liquid.waves;
  EXPECT_EQ(waves.dimple_xz, mid.crater_xz);
  EXPECT_GT(waves.dimple_depth, 0.001);
  EXPECT_LT(waves.dimple_depth, 0.01);
  double bottom = 1e9;  // the stream's lowest reach: a blob's centre less its radius
  for (std::size_t i = 0; i < streams[0].points->size(); ++i)
    bottom = std::min(bottom, double(streams[0].points->position[i].y) - double(streams[0].points->radius_of(i)));
  EXPECT_LT(bottom, sim.vessel().fill_height(sim.fraction()) - 0.5 * waves.dimple_depth)
      << "the stream reaches down into the dimple";
  // Once the last of it has landed the foam and the drink flow back within a second or so.
  for (int i = 1; i <= int(2.5 / kPourDt); ++i) sim.step(MotionSample{});
  ASSERT_FALSE(sim.pouring());
  EXPECT_EQ(sim.frame().foam.crater_depth, 0.0);
  EXPECT_EQ(sim.frame().liquid.waves.dimple_depth, 0.0);
}

TEST(Pour, NoDurationFillsAtOnce) {
  Simulation sim(pour_lager_in_pint(0.6f));
  sim.set_fraction(0.1);
  sim.pour_over(0);
  EXPECT_DOUBLE_EQ(sim.fraction(), double(0.6f));
  EXPECT_FALSE(sim.pouring());
  EXPECT_TRUE(sim.streams().empty());
}

TEST(Pour, WhatSpillsOverTheRimFallsAsAStreamOfTheSameVolume) {
  const Params p = pour_lager_in_pint(0.86f);
  Simulation sim(p);
  sim.pour();
  const double foot = sim.vessel().outer_radius(0);
  double spilled_seen = 0;
  bool stream = false;
  for (int i = 1; i <= int(3.0 / kPourDt); ++i) {
    const double t = i * kPourDt, u = std::clamp(t / 1.5, 0.0, 1.0);
    MotionSample m;
    m.time = t;
    m.pose = tipped_on_floor(tilt_orientation(u * u * (3 - 2 * u) * 1.4, 0.0), foot);  // to 80 degrees
    sim.step(m);
    for (const CloudFrame& s : sim.streams()) {
      stream = true;
      // It falls from the rim on the side the glass tips to (+X) towards the floor.
      double x = 0;
      for (const glm::vec3& q : s.points->position) x += q.x;
      EXPECT_GT(x / double(s.points->size()), 0.0);
    }
    spilled_seen = sim.spilled();
  }
  EXPECT_GT(spilled_seen, 0.3);
  EXPECT_TRUE(stream) << "the spill is seen";
}

TEST(Pour, ThePourActionTakesADuration) {
  auto parse = [](const std::string& actions) {
    return parse_timeline(R"({"draught_timeline": 1, "actions": )" + actions + "}", "t.json");
  };
  const Timeline a = parse(R"([{"at": 1, "action": "pour"}])");
  ASSERT_TRUE(a.pours_in(0.9, 1.1));
  EXPECT_DOUBLE_EQ(*a.pours_in(0.9, 1.1), kPourSeconds);
  EXPECT_DOUBLE_EQ(*parse(R"([{"at": 0, "action": "pour", "duration": 0}])").pours_in(0, 0.1), 0.0);
  EXPECT_DOUBLE_EQ(*parse(R"([{"at": 0, "action": "pour", "duration": 4.5}])").pours_in(0, 0.1), 4.5);
  EXPECT_THROW(parse(R"([{"at": 0, "action": "pour", "duration": 31}])"), InputError);
}

}  // namespace
}  // namespace draught
