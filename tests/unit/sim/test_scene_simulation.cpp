// SceneSimulation: each vessel of a scene has its own Simulation at its placement; input
// drives the selected one, the others stay at rest; a scene of one glass moves exactly
// as a Simulation of its own; the same input gives the same frames.
#include "core/params/preset.hpp"
#include "core/sim/scene_simulation.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

namespace draught {
namespace {

// Tips the glass towards +X by up to 25 degrees over the first second (on its foot).
struct SceneTipDriver : InputDriver {
  double foot;
  explicit SceneTipDriver(double f) : foot(f) {}
  const char* name() const override { return "tip"; }
  static double angle(double t) {
    const double u = std::clamp(t, 0.0, 1.0);
    return 25.0 * kPi / 180 * u * u * (3 - 2 * u);
  }
  Pose pose(double t) const { return tipped_on_floor(tilt_orientation(angle(t), 0.0), foot); }
  MotionSample sample(double t) override {
    const double h = 1e-4;
    MotionSample m;
    m.time = t;
    m.pose = pose(t);
    m.angular_velocity = glm::dvec3(0, 0, -1) * (angle(t + h) - angle(t - h)) / (2 * h);
    m.linear_acceleration = (pose(t + h).position - 2.0 * m.pose.position + pose(t - h).position) / (h * h);
    return m;
  }
};

const Scene& flight() {
  static const Scene s = resolve_scene_objects({"flight", "", {}, {}});
  return s;
}

// The world angle between the vessel's axis and up, degrees.
double axis_tilt(const VesselFrame& f) { return tilt_angle(f.pose.orientation) * 180 / kPi; }

bool bit_equal(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool bit_equal(const glm::dvec3& a, const glm::dvec3& b) { return bit_equal(a.x, b.x) && bit_equal(a.y, b.y) && bit_equal(a.z, b.z); }
bool bit_equal(const glm::dquat& a, const glm::dquat& b) {
  return bit_equal(a.w, b.w) && bit_equal(a.x, b.x) && bit_equal(a.y, b.y) && bit_equal(a.z, b.z);
}

bool same_vessel(const VesselParams& a, const VesselParams& b) {
  for (const auto& d : param_table())
    if (d.scope == ParamScope::Vessel && !(get_param(a, d) == get_param(b, d))) return false;
  return true;
}

::testing::AssertionResult same_vessel_frame(const VesselFrame& a, const VesselFrame& b) {
  if (!bit_equal(a.pose.orientation, b.pose.orientation) || !bit_equal(a.pose.position, b.pose.position))
    return ::testing::AssertionFailure() << "pose differs";
  if (!bit_equal(a.liquid.n, b.liquid.n) || !bit_equal(a.liquid.offset, b.liquid.offset))
    return ::testing::AssertionFailure() << "liquid plane differs";
  if (!bit_equal(a.liquid.waves.ring, b.liquid.waves.ring) || !bit_equal(a.liquid_fraction, b.liquid_fraction))
    return ::testing::AssertionFailure() << "waves or volume differ";
  if (!bit_equal(a.foam.thickness, b.foam.thickness)) return ::testing::AssertionFailure() << "foam differs";
  if (a.bubbles.size() != b.bubbles.size()) return ::testing::AssertionFailure() << "bubble count differs";
  for (size_t i = 0; i < a.bubbles.size(); ++i)
    if (std::memcmp(&a.bubbles[i].p, &b.bubbles[i].p, sizeof(glm::vec3)) != 0) return ::testing::AssertionFailure() << "bubble " << i << " differs";
  return ::testing::AssertionSuccess();
}

TEST(SceneSimulation, OneSimulationPerVesselAtItsPlace) {
  const SceneSimulation sim(flight());
  ASSERT_EQ(sim.scene().objects.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    ASSERT_NE(sim.vessel(i), nullptr) << i;
    for (int j = 0; j < i; ++j) EXPECT_NE(sim.vessel(i), sim.vessel(j));
    EXPECT_TRUE(same_vessel(sim.vessel(i)->params(), as_vessel(flight().objects[size_t(i)])->params)) << i;
  }
  EXPECT_EQ(sim.vessel(4), nullptr);
  const FrameState f = sim.frame();
  ASSERT_EQ(f.vessels.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    const glm::vec3 at = flight().objects[i].placement.position;
    EXPECT_EQ(f.vessels[i].placement.position, at) << i;
    EXPECT_NEAR(f.vessels[i].pose.position.x, at.x, 1e-12) << i;
    EXPECT_NEAR(f.vessels[i].pose.position.z, at.z, 1e-12) << i;
    EXPECT_NEAR(axis_tilt(f.vessels[i]), 0.0, 1e-9) << i;
  }
  // Different glasses: the weizen is the tallest.
  EXPECT_GT(sim.vessel(3)->vessel().height, sim.vessel(2)->vessel().height);
}

TEST(SceneSimulation, TiltingTheSelectedGlassLeavesTheOthersLevel) {
  SceneSimulation sim(flight());
  sim.select(1);
  ASSERT_EQ(sim.selected(), 1);
  SceneTipDriver tip(sim.vessel(1)->vessel().r_outer.front());
  sim.advance(tip, 1.5);
  const FrameState f = sim.frame();
  EXPECT_EQ(f.selected, 1);
  EXPECT_NEAR(axis_tilt(f.vessels[1]), 25.0, 0.01) << "the selected glass tipped";
  // Tipped about its own foot at its own place, not about the world's origin.
  EXPECT_NEAR(f.vessels[1].pose.position.x, flight().objects[1].placement.position.x, 0.05);
  // Its drink stays level in the world: tilted by the glass's tilt in the glass's frame.
  EXPECT_NEAR(std::acos(sim.vessel(1)->surface().n.y) * 180 / kPi, 25.0, 0.5);
  for (int i : {0, 2, 3}) {
    EXPECT_EQ(axis_tilt(f.vessels[size_t(i)]), 0.0) << i;
    EXPECT_EQ(sim.vessel(i)->energy(), 0.0) << "object " << i << " sloshes without being moved";
    const glm::dvec3 n = sim.vessel(i)->surface().n;
    EXPECT_EQ(n, glm::dvec3(0, 1, 0)) << "object " << i << "'s surface is not level";
    EXPECT_EQ(sim.vessel(i)->time(), sim.vessel(1)->time()) << "one clock for every object";
  }
  // Selecting another glass then moves that one.
  sim.select(99);
  EXPECT_EQ(sim.selected(), 3) << "clamped to the objects there are";
}

TEST(SceneSimulation, SameInputGivesBitIdenticalFrames) {
  SceneSimulation a(flight()), b(flight());
  a.select(2), b.select(2);
  a.settle_bubbles(1.0), b.settle_bubbles(1.0);
  SceneTipDriver ta(a.vessel(2)->vessel().r_outer.front()), tb(b.vessel(2)->vessel().r_outer.front());
  for (double t = 0.25; t <= 2.0; t += 0.25) {
    a.advance(ta, t, 0.02);
    b.advance(tb, t, 0.02);
    const FrameState fa = a.frame(), fb = b.frame();
    ASSERT_EQ(fa.vessels.size(), fb.vessels.size());
    for (size_t i = 0; i < fa.vessels.size(); ++i) ASSERT_TRUE(same_vessel_frame(fa.vessels[i], fb.vessels[i])) << t << " " << i;
  }
  EXPECT_LT(a.vessel(2)->fraction(), double(as_vessel(flight().objects[2])->params.liquid.fill)) << "the selected one drank";
  EXPECT_EQ(a.vessel(0)->fraction(), double(as_vessel(flight().objects[0])->params.liquid.fill)) << "the others did not";
}

TEST(SceneSimulation, OneGlassMovesExactlyAsASimulationOfItsOwn) {
  const Params p = resolve_scene({"lager", "pint", {}, {}});
  SceneSimulation scene(single_glass_scene(p));
  Simulation single(p);
  scene.settle_bubbles(2.0);
  single.settle_bubbles(2.0);
  SceneTipDriver d1(single.vessel().r_outer.front()), d2(single.vessel().r_outer.front());
  for (double t = 0.1; t <= 2.0; t += 0.1) {
    scene.advance(d1, t, 0.05);
    single.advance(d2, t, 0.05);
    ASSERT_TRUE(same_vessel_frame(scene.frame().vessels.at(0), single.frame())) << t;
  }
  // And its frame is the single glass's frame.
  const FrameState fs = scene.frame(), f1 = assemble_frame(p, {single.frame()});
  EXPECT_EQ(fs.camera.eye, f1.camera.eye);
  EXPECT_EQ(fs.camera.target, f1.camera.target);
}

TEST(SceneSimulation, StepEachMovesEveryObjectWithItsOwnMotion) {
  SceneSimulation sim(flight());
  std::vector<MotionSample> motions(4);
  for (int k = 1; k <= 240; ++k) {
    const double t = k * Simulation::kStep;
    for (size_t i = 0; i < 4; ++i) {
      motions[i] = MotionSample{};
      motions[i].time = t;
    }
    SceneTipDriver tip(sim.vessel(3)->vessel().r_outer.front());
    motions[3] = tip.sample(t);
    sim.step_each(motions, {0.0, 0.1, 0.0, 0.0});
  }
  const FrameState f = sim.frame();
  EXPECT_NEAR(axis_tilt(f.vessels[3]), 25.0, 0.01);
  EXPECT_EQ(axis_tilt(f.vessels[0]), 0.0);
  EXPECT_NEAR(sim.vessel(1)->fraction(), double(as_vessel(flight().objects[1])->params.liquid.fill) - 0.1, 1e-9)
      << "object 1 drank for a second at 0.1 per second";
  EXPECT_EQ(sim.vessel(0)->fraction(), double(as_vessel(flight().objects[0])->params.liquid.fill));
}

TEST(SceneSimulation, NewParametersKeepTheStateOfUnchangedGlasses) {
  SceneSimulation sim(flight());
  sim.select(0);
  SceneTipDriver tip(sim.vessel(0)->vessel().r_outer.front());
  sim.advance(tip, 0.5);
  const double energy = sim.vessel(0)->energy();
  ASSERT_GT(energy, 0.0);
  Scene changed = flight();
  set_param(changed, parse_param_ref(changed, "objects[2].liquid.srm"), 20.0f);
  sim.set_scene(changed);
  EXPECT_EQ(sim.vessel(0)->energy(), energy) << "object 0 kept its slosh";
  EXPECT_EQ(sim.vessel(2)->params().liquid.srm, 20.0f);
}

// The surroundings' light an app's frames reuse (EnvironmentCache): every frame is the one
// assemble_frame makes without the cache, bit for bit, while a glass tips, its drink is
// drunk, the heads settle and the studio's parameters change.
::testing::AssertionResult same_surroundings(const FrameState& a, const FrameState& b) {
  auto same = [](const SkyIrradiance& x, const SkyIrradiance& y) {
    for (size_t k = 0; k < x.coef.size(); ++k)
      if (!bit_equal(x.coef[k], y.coef[k])) return false;
    return true;
  };
  if (!same(a.environment.sky, b.environment.sky) || !same(a.environment.surround, b.environment.surround) ||
      !a.environment.paper_bounce || !b.environment.paper_bounce ||
      a.environment.paper_bounce->bounce != b.environment.paper_bounce->bounce ||
      !same(a.environment.media.surround, b.environment.media.surround))
    return ::testing::AssertionFailure() << "the scene's surroundings differ";
  if (a.environment.media_seen_from.size() != b.environment.media_seen_from.size())
    return ::testing::AssertionFailure() << "a head's view is missing";
  for (size_t k = 0; k < a.environment.media_seen_from.size(); ++k)
    if (!same(a.environment.media_seen_from[k], b.environment.media_seen_from[k]))
      return ::testing::AssertionFailure() << "head " << k << " sees other surroundings";
  for (size_t i = 0; i < a.vessels.size(); ++i)
    if (!same(a.vessels[i].head_surround, b.vessels[i].head_surround))
      return ::testing::AssertionFailure() << "vessel " << i << "'s head sees other surroundings";
  if (a.environment.reflected != b.environment.reflected || a.environment.glint != b.environment.glint)
    return ::testing::AssertionFailure() << "the bubbles' reflection differs";
  return ::testing::AssertionSuccess();
}

TEST(SceneSimulation, TheSurroundingsKeptBetweenFramesAreTheOnesItWouldCompute) {
  SceneSimulation sim(flight());
  sim.select(2);
  SceneTipDriver tip(sim.vessel(2)->vessel().r_outer.front());
  Scene changed = flight();
  for (double t = 0.25; t <= 3.0; t += 0.25) {
    sim.advance(tip, t, 0.02);
    if (t == 1.5) {  // the studio changes under the frames
      set_param(changed, parse_param_ref(changed, "env.intensity"), 0.6f);
      set_param(changed, parse_param_ref(changed, "light.power"), 9.0f);
      sim.set_scene(changed);
    }
    if (t == 2.5) {
      set_param(changed, parse_param_ref(changed, "env.sweep_color"), glm::vec3(0.5f, 0.6f, 0.7f));
      sim.set_scene(changed);
    }
    const FrameState kept = sim.frame();
    const FrameState fresh = assemble_frame(kept.params, kept.vessels, kept.selected, kept.time);
    ASSERT_TRUE(same_surroundings(kept, fresh)) << "at " << t << " s";
  }
}

// ... and it is reused: a still scene's second frame takes the scene's part and each
// head's view from the cache; a new parameter or a moved head does not.
TEST(SceneSimulation, AStillSceneReusesItsSurroundings) {
  const FrameState f = make_frame(flight());
  EnvironmentCache cache;
  assemble_frame(f.params, f.vessels, 0, 0, &cache);
  ASSERT_EQ(cache.views.size(), 4u);
  // Marked, so that a frame that took them from the cache shows it.
  cache.scene.sky.coef[0].x = 123.0;
  cache.views[1].second.coef[0].y = 456.0;
  const FrameState again = assemble_frame(f.params, f.vessels, 0, 0, &cache);
  EXPECT_EQ(again.environment.sky.coef[0].x, 123.0);
  EXPECT_EQ(again.vessels[1].head_surround.coef[0].y, 456.0);
  // A head a millimetre lower is seen again; the others are kept.
  std::vector<VesselFrame> settled = f.vessels;
  settled[1].foam.thickness -= 2e-3;
  const FrameState lower = assemble_frame(f.params, settled, 0, 0, &cache);
  EXPECT_NE(lower.vessels[1].head_surround.coef[0].y, 456.0);
  EXPECT_EQ(lower.environment.sky.coef[0].x, 123.0);
  // A parameter of the studio: everything again.
  SceneParams brighter = f.params;
  brighter.env.intensity = 1.5f;
  const FrameState changed = assemble_frame(brighter, f.vessels, 0, 0, &cache);
  EXPECT_NE(changed.environment.sky.coef[0].x, 123.0);
  EXPECT_TRUE(same_surroundings(changed, assemble_frame(brighter, f.vessels)));
}

// A glass the selection leaves is put back upright smoothly (its drink sloshes as when a
// hand sets a glass down), not snapped to rest; the newly selected glass follows input.
TEST(SceneSimulation, ReleasedGlassEasesBackUpright) {
  SceneSimulation sim(flight());
  sim.select(0);
  SceneTipDriver tip(sim.vessel(0)->vessel().r_outer.front());
  sim.advance(tip, 1.2);
  ASSERT_NEAR(axis_tilt(sim.frame().vessels[0]), 25.0, 0.5);
  sim.select(1);
  const double t0 = sim.time();
  struct Still : InputDriver {
    const char* name() const override { return "still"; }
    MotionSample sample(double t) override { MotionSample m; m.time = t; return m; }
  } still;
  sim.advance(still, t0 + 0.1);
  const double early = axis_tilt(sim.frame().vessels[0]);
  EXPECT_GT(early, 15.0) << "let go, not snapped upright";
  sim.advance(still, t0 + 0.3);
  const double mid = axis_tilt(sim.frame().vessels[0]);
  EXPECT_LT(mid, early);
  EXPECT_GT(mid, 1.0);
  sim.advance(still, t0 + 0.7);
  EXPECT_LT(axis_tilt(sim.frame().vessels[0]), 1e-6);
  EXPECT_LT(axis_tilt(sim.frame().vessels[1]), 1e-6);
  EXPECT_GT(sim.vessel(0)->energy(), 0.0) << "setting it down moves the drink";
}

// An app whose clock has run (the web page) loads a scene of a gob: begun at its time, the
// gob is as it is in a scene begun at 0 (as hot, as turned), not aged by the app's clock.
TEST(SceneSimulation, ASceneBegunLaterCountsItsCloudsTimeFromThere) {
  const Scene scene = scene_from_preset(parse_preset(R"({"draught_preset": 1, "kind": "scene", "name": "g",
    "objects": [{"name": "gob", "kind": "pointcloud", "pointcloud": {"count": 600}}]})", "g.json"));
  struct Still : InputDriver {
    const char* name() const override { return "still"; }
    MotionSample sample(double t) override { MotionSample m; m.time = t; return m; }
  } still;
  auto mean_kelvin = [](const SceneSimulation& s) {
    const PointCloud& c = *s.frame().clouds.at(0).points;
    double sum = 0;
    for (float k : c.temperature) sum += k;
    return sum / double(c.size());
  };
  SceneSimulation fresh(scene);
  fresh.advance(still, 0.5);
  SceneSimulation later(scene);
  later.begin_at(20.0);
  later.advance(still, 20.5);
  EXPECT_NEAR(later.time(), 20.5, 1e-6);
  EXPECT_NEAR(mean_kelvin(later), mean_kelvin(fresh), 1.0);
  SceneSimulation aged(scene);  // not begun: its clouds count from 0, twenty seconds of cooling
  aged.advance(still, 20.5);
  EXPECT_LT(mean_kelvin(aged), mean_kelvin(fresh) - 20.0);  // (33 K cooler: a gob keeps its heat)
}

}  // namespace
}  // namespace draught
