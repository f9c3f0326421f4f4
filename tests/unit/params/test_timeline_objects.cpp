// Timelines that address objects of a scene ("object": N or "name", set on
// objects[N].path), their errors (file and actions[i].object), binding to a scene, and
// playing on a SceneSimulation; a single glass plays exactly as before.
#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/scene/frame.hpp"
#include "core/sim/scene_simulation.hpp"
#include "core/sim/simulation.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

namespace draught {
namespace {

using test::has;

std::string timeline_json(const std::string& actions, const std::string& extra = "") {
  return R"({ "draught_timeline": 1, "name": "t", )" + extra + R"("actions": )" + actions + " }";
}

Timeline parse(const std::string& actions, const std::string& extra = "") {
  return parse_timeline(timeline_json(actions, extra), "t.json");
}

std::string timeline_parse_error(const std::string& actions) {
  return test::input_error_of([&] { parse(actions); });
}

std::string bind_error(const std::string& actions, const Scene& scene) {
  return test::input_error_of([&] {
    Timeline t = parse(actions);
    bind_timeline(t, scene);
  });
}

const Scene& flight() {
  static const Scene s = resolve_scene_objects({"flight", "", {}, {}});
  return s;
}

double axis_tilt_deg(const VesselFrame& f) { return tilt_angle(f.pose.orientation) * 180 / kPi; }

// ------------------------------------------------------------------ parsing --

TEST(TimelineObjects, ParsesIndexNameAndObjectPaths) {
  const Timeline t = parse(R"([
      { "at": 0, "action": "tilt", "angle": 20, "object": 2 },
      { "at": 0, "action": "sip", "amount": 0.1, "object": "stout" },
      { "at": 0, "action": "set", "param": "objects[1].liquid.srm", "value": 20 },
      { "at": 0, "action": "set", "param": "liquid.haze", "value": 5, "object": 3 },
      { "at": 0, "action": "pour" } ])");
  ASSERT_EQ(t.actions.size(), 5u);
  EXPECT_EQ(t.actions[0].object, 2);
  EXPECT_EQ(t.actions[0].object_field, "actions[0].object");
  EXPECT_EQ(t.actions[1].object, kUnboundObject);
  EXPECT_EQ(t.actions[1].object_name, "stout");
  EXPECT_EQ(t.actions[2].object, 1);
  EXPECT_EQ(t.actions[2].param, find_param("liquid.srm"));
  EXPECT_EQ(t.actions[2].object_field, "actions[2].param");
  EXPECT_EQ(t.actions[3].object, 3);
  EXPECT_EQ(t.actions[4].object, -1) << "no object: every vessel";
  EXPECT_TRUE(t.actions[4].object_field.empty());
}

TEST(TimelineObjects, ParseErrorsNameFileAndField) {
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "at": 0, "action": "tilt", "angle": 10 }, { "action": "sip", "amount": 0.1, "object": -1 }])"),
                  {"t.json", "field 'actions[1].object'", "from 0 to 63", "got -1"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "sip", "amount": 0.1, "object": 64 }])"), {"actions[0].object", "got 64"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "sip", "amount": 0.1, "object": 1.5 }])"), {"actions[0].object"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "sip", "amount": 0.1, "object": "" }])"), {"actions[0].object"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "pour", "object": true }])"), {"actions[0].object", "got true"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "orbit", "degrees": 30, "object": 1 }])"),
                  {"t.json", "actions[0].object", "orbit moves the camera"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "set", "param": "objects[1].liquid.srm", "value": 3, "object": 1 }])"),
                  {"actions[0].object", "already names its object"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "set", "param": "objects[1].env.floor", "value": false }])"),
                  {"actions[0].param", "env.floor belongs to the whole scene"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "set", "param": "env.floor", "value": false, "object": 0 }])"),
                  {"actions[0].object", "whole scene"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "set", "param": "objects[x].liquid.srm", "value": 3 }])"),
                  {"actions[0].param", "objects[2].liquid.fill"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "set", "param": "objects[64].liquid.srm", "value": 3 }])"),
                  {"actions[0].param", "from 0 to 63"}));
  EXPECT_TRUE(has(timeline_parse_error(R"([{ "action": "set", "param": "objects[1].liquid.sr", "value": 3 }])"),
                  {"actions[0].param", "did you mean 'liquid.srm'"}));
}

// ------------------------------------------------------------------ binding --

TEST(TimelineObjects, BindResolvesNamesAndChecksIndexes) {
  Timeline t = parse(R"([{ "at": 1, "action": "sip", "amount": 0.1, "object": "hefeweizen" },
                         { "at": 0, "action": "tilt", "angle": 10, "object": "amber-ale" }])");
  bind_timeline(t, flight());
  // Sorted by time; the name found in the scene.
  EXPECT_EQ(t.actions[0].object, 1);
  EXPECT_EQ(t.actions[1].object, 3);
  // Errors name the action as it is in the file (actions[1] although it sorts first).
  const std::string late_first = R"([{ "at": 5, "action": "pour" }, { "at": 0, "action": "tilt", "angle": 10, "object": "stuot" }])";
  EXPECT_TRUE(has(bind_error(late_first, flight()),
                  {"t.json", "field 'actions[1].object'", "from 0 to 3", "\"pilsner\"", "\"hefeweizen\"",
                   "got \"stuot\"", "did you mean \"stout\"?"}));
  EXPECT_TRUE(has(bind_error(R"([{ "action": "sip", "amount": 0.1 }, { "action": "pour", "object": 4 }])", flight()),
                  {"t.json", "field 'actions[1].object'", "an object index from 0 to 3 (the scene has 4 objects)", "got 4"}));
  EXPECT_TRUE(has(bind_error(R"([{ "action": "set", "param": "objects[7].liquid.fill", "value": 0.5 }])", flight()),
                  {"t.json", "field 'actions[0].param'", "from 0 to 3", "got 7"}));
  // A single glass is object 0, named "glass".
  const Scene one = single_glass_scene(default_params());
  EXPECT_EQ(bind_error(R"([{ "action": "pour", "object": 0 }, { "action": "pour", "object": "glass" }])", one), "no error");
  EXPECT_TRUE(has(bind_error(R"([{ "action": "pour", "object": 1 }])", one), {"from 0 to 0"}));
}

TEST(TimelineObjects, UnboundNamesDriveNothing) {
  const Timeline t = parse(R"([{ "at": 0, "action": "tilt", "angle": 20, "duration": 1, "object": "stout" }])");
  EXPECT_EQ(t.lean_at(2.0, 0), glm::dvec2(0.0));
  EXPECT_EQ(t.lean_at(2.0, 2), glm::dvec2(0.0));
}

// ------------------------------------------------------- what each object sees --

TEST(TimelineObjects, MotionActionsDriveTheirObjectOrEvery) {
  Timeline t = parse(R"([
      { "at": 0, "action": "tilt", "angle": 20, "duration": 1, "object": 2 },
      { "at": 0, "action": "rotate", "degrees": 90, "duration": 1, "object": "pilsner" },
      { "at": 0, "action": "shake", "amplitude": 0.01, "frequency": 2, "duration": 2, "object": 1 },
      { "at": 0, "action": "sip", "amount": 0.2, "duration": 1, "object": 3 },
      { "at": 1, "action": "pour", "object": 1 },
      { "at": 3, "action": "tilt", "angle": 10, "duration": 1 } ])");
  bind_timeline(t, flight());
  EXPECT_NEAR(glm::length(t.lean_at(1.5, 2)), 20 * kPi / 180, 1e-12);
  for (int i : {0, 1, 3}) EXPECT_EQ(t.lean_at(1.5, i), glm::dvec2(0.0)) << i;
  for (int i : {0, 1, 2, 3}) EXPECT_NEAR(glm::length(t.lean_at(5, i)), 10 * kPi / 180, 1e-12) << "every object " << i;
  EXPECT_NEAR(t.spin_at(2, 0), kPi / 2, 1e-12);
  EXPECT_EQ(t.spin_at(2, 1), 0.0);
  EXPECT_NE(t.shake_at(0.6, 1), glm::dvec3(0.0));
  EXPECT_EQ(t.shake_at(0.6, 0), glm::dvec3(0.0));
  EXPECT_NEAR(t.drink_rate_at(0.5, 3), 0.2, 1e-12);
  EXPECT_EQ(t.drink_rate_at(0.5, 2), 0.0);
  EXPECT_TRUE(t.pours_in(0.9, 1.1, 1));
  EXPECT_FALSE(t.pours_in(0.9, 1.1, 0));
}

TEST(TimelineObjects, SetActionsBlendEachObjectFromItsOwnValue) {
  Timeline t = parse(R"([
      { "at": 0, "action": "set", "param": "objects[2].liquid.srm", "value": 10, "duration": 2, "ease": "linear" },
      { "at": 0, "action": "set", "param": "liquid.fill", "value": 0.5, "duration": 2, "ease": "linear" },
      { "at": 0, "action": "set", "param": "env.floor", "value": false } ])");
  bind_timeline(t, flight());
  const Scene s = t.scene_at(1.0, flight());
  for (size_t i = 0; i < 4; ++i) {
    const VesselParams& was = as_vessel(flight().objects[i])->params;
    const VesselParams& now = as_vessel(s.objects[i])->params;
    EXPECT_FLOAT_EQ(now.liquid.fill, 0.5f * (was.liquid.fill + 0.5f)) << "halfway from its own fill, object " << i;
    if (i == 2) { EXPECT_FLOAT_EQ(now.liquid.srm, 0.5f * (was.liquid.srm + 10.0f)); }
    else { EXPECT_EQ(now.liquid.srm, was.liquid.srm) << i; }
  }
  EXPECT_FALSE(s.params.env.floor);
  // The single-glass view: object 0 only.
  const Params p = t.params_at(2.0, vessel_document(flight(), 0));
  EXPECT_EQ(p.liquid.fill, 0.5f);
  EXPECT_EQ(p.liquid.srm, as_vessel(flight().objects[0])->params.liquid.srm);
}

// ------------------------------------------------------------------ playing --

TEST(TimelineObjects, PlayedOnAScene) {
  const Timeline t = parse(R"([
      { "at": 0.2, "action": "tilt", "angle": 20, "duration": 0.8, "object": "stout" },
      { "at": 0.2, "action": "sip", "amount": 0.2, "duration": 0.5, "object": 1 } ])");
  const FrameState f = timeline_frame(t, flight(), 1.5);
  ASSERT_EQ(f.vessels.size(), 4u);
  EXPECT_NEAR(axis_tilt_deg(f.vessels[2]), 20.0, 0.01);
  for (size_t i : {0u, 1u, 3u}) EXPECT_EQ(axis_tilt_deg(f.vessels[i]), 0.0) << i;
  const double fill1 = as_vessel(flight().objects[1])->params.liquid.fill;
  EXPECT_NEAR(f.vessels[1].liquid_fraction, fill1 - 0.2, 0.002);
  EXPECT_EQ(f.vessels[0].liquid_fraction, double(as_vessel(flight().objects[0])->params.liquid.fill));
  // Tipped on its own foot at its own place.
  EXPECT_NEAR(f.vessels[2].pose.position.x, flight().objects[2].placement.position.x, 0.05);
  // An action for every vessel tips all four alike.
  const FrameState all = timeline_frame(parse(R"([{ "at": 0, "action": "tilt", "angle": 15, "duration": 0.5 }])"), flight(), 1.0);
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR(axis_tilt_deg(all.vessels[i]), 15.0, 0.01) << i;
  // A timeline naming an object the scene lacks is refused.
  EXPECT_THROW(timeline_frame(parse(R"([{ "action": "pour", "object": "cider" }])"), flight(), 0.5), InputError);
}

TEST(TimelineObjects, SceneTimelinesAreDeterministic) {
  const Timeline t = parse(R"([
      { "at": 0, "action": "shake", "amplitude": 0.008, "frequency": 3, "duration": 1, "object": 0 },
      { "at": 0.5, "action": "tilt", "angle": 30, "duration": 1 } ])");
  const FrameState a = timeline_frame(t, flight(), 1.7), b = timeline_frame(t, flight(), 1.7);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(std::memcmp(&a.vessels[i].pose, &b.vessels[i].pose, sizeof(Pose)), 0) << i;
    EXPECT_EQ(a.vessels[i].liquid.n, b.vessels[i].liquid.n) << i;
    EXPECT_EQ(a.vessels[i].liquid.offset, b.vessels[i].liquid.offset) << i;
  }
}

TEST(TimelineObjects, SingleGlassPlaysBitForBitAsBefore) {
  // The Simulation path (what the viewer and the CLI did) and the SceneSimulation path give
  // identical frames for every shipped timeline.
  for (const char* name : {"gentle-tilt", "shake-and-settle", "tilt-until-spill", "fresh-pour"}) {
    const Timeline tl = load_timeline(name);
    const Params base = resolve_scene({tl.preset.empty() ? "lager" : tl.preset, tl.glass, {}, {}});
    Simulation sim(tl.params_at(0, base));
    sim.settle_bubbles(4.0);
    TimelineDriver driver(tl, sim.vessel().r_outer.front());
    for (double t : {0.5, 1.3, 2.6, 4.1}) {
      play_timeline(sim, driver, tl, base, t);
      const FrameState old_way = assemble_frame(tl.params_at(t, base), {sim.frame()});
      const FrameState new_way = timeline_frame(tl, base, t);
      ASSERT_EQ(new_way.vessels.size(), 1u);
      const VesselFrame &o = old_way.vessels[0], &n = new_way.vessels[0];
      EXPECT_EQ(std::memcmp(&o.pose, &n.pose, sizeof(Pose)), 0) << name << " " << t;
      EXPECT_EQ(o.liquid.n, n.liquid.n) << name << " " << t;
      EXPECT_EQ(o.liquid.offset, n.liquid.offset) << name << " " << t;
      EXPECT_EQ(o.liquid.waves.ring, n.liquid.waves.ring) << name << " " << t;
      EXPECT_EQ(o.liquid_fraction, n.liquid_fraction) << name << " " << t;
      EXPECT_EQ(o.foam.thickness, n.foam.thickness) << name << " " << t;
      ASSERT_EQ(o.bubbles.size(), n.bubbles.size()) << name << " " << t;
      for (size_t i = 0; i < o.bubbles.size(); ++i) ASSERT_EQ(o.bubbles[i].p, n.bubbles[i].p) << name << " " << t;
      EXPECT_EQ(old_way.camera.eye, new_way.camera.eye) << name << " " << t;
    }
  }
}

}  // namespace
}  // namespace draught
