// Scene presets that place several objects: parsing, every validation error (each names
// the file and the field), resolving them into a Scene, and --set on objects.
#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/vessel/vessel.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace draught {
namespace {

using test::has;

namespace fs = std::filesystem;

// A scene preset with these objects (JSON array text) and optional top-level params.
std::string scene_json(const std::string& objects, const std::string& params = "{}", const std::string& extra = "") {
  return R"({ "draught_preset": 1, "kind": "scene", "name": "s", )" + extra + R"("params": )" + params +
         R"(, "objects": )" + objects + " }";
}

// Two glasses far apart: a lager in a pint and a stout in a nonic.
const std::string kTwo = R"([
  { "name": "a", "glass": "pint", "drink": "lager", "position": [-0.1, 0, 0] },
  { "name": "b", "glass": "nonic", "drink": "stout", "position": [0.1, 0, 0.02], "yaw": 30 } ])";

std::string scene_parse_error(const std::string& text) {
  try {
    parse_preset(text, "s.json");
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong exception type: ") + e.what();
  }
  return "no error";
}

// The error of parsing and then resolving the scene (glass and drink names, footprints).
std::string scene_error(const std::string& text) {
  try {
    scene_from_preset(parse_preset(text, "s.json"));
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong exception type: ") + e.what();
  }
  return "no error";
}

VesselParams vessel_of(const Scene& s, size_t i) { return as_vessel(s.objects.at(i))->params; }

::testing::AssertionResult same_vessel(const VesselParams& a, const VesselParams& b) {
  for (const auto& d : param_table())
    if (d.scope == ParamScope::Vessel && !(get_param(a, d) == get_param(b, d)))
      return ::testing::AssertionFailure() << d.path << " differs";
  return ::testing::AssertionSuccess();
}

// ------------------------------------------------------------------- parsing --

TEST(ScenePreset, ParsesObjects) {
  const Preset p = parse_preset(scene_json(kTwo, R"({ "env": { "floor": false } })"), "s.json");
  EXPECT_EQ(p.kind, "scene");
  ASSERT_EQ(p.objects.size(), 2u);
  EXPECT_EQ(p.objects[0].name, "a");
  EXPECT_EQ(p.objects[0].glass, "pint");
  EXPECT_EQ(p.objects[0].drink, "lager");
  EXPECT_EQ(p.objects[0].placement.position, glm::vec3(-0.1f, 0.0f, 0.0f));
  EXPECT_EQ(p.objects[1].placement.position, glm::vec3(0.1f, 0.0f, 0.02f));
  EXPECT_EQ(p.objects[1].placement.yaw, 30.0f);
  ASSERT_EQ(p.values.size(), 1u);
  EXPECT_EQ(p.values[0].first->path, "env.floor");
}

TEST(ScenePreset, ShippedFlight) {
  const Preset p = load_preset(test::preset_source_dir() / "scenes" / "flight.json");
  EXPECT_EQ(p.name, "flight");
  ASSERT_EQ(p.objects.size(), 4u);
  const std::vector<std::pair<std::string, std::string>> want = {
      {"pilsner", "pilsner"}, {"tulip", "amber-ale"}, {"nonic", "stout"}, {"weizen", "hefeweizen"}};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(p.objects[i].glass, want[i].first) << i;
    EXPECT_EQ(p.objects[i].drink, want[i].second) << i;
    if (i > 0) { EXPECT_GT(p.objects[i].placement.position.x, p.objects[i - 1].placement.position.x) << "side by side, left to right"; }
  }
  const Scene s = scene_from_preset(p);
  ASSERT_EQ(s.objects.size(), 4u);
  // Each object is its drink in its glass, exactly as a single-glass render of the pair.
  for (size_t i = 0; i < 4; ++i) {
    const Params single = resolve_scene({want[i].second, want[i].first, {}, {}});
    EXPECT_TRUE(same_vessel(vessel_of(s, i), single)) << i;
    EXPECT_EQ(s.objects[i].name, p.objects[i].name);
  }
  // The glasses do not touch: at least 1 cm between neighbouring footprints.
  for (size_t i = 1; i < 4; ++i) {
    const double gap = double(s.objects[i].placement.position.x - s.objects[i - 1].placement.position.x) -
                       build_vessel(vessel_of(s, i).glass).bound_radius -
                       build_vessel(vessel_of(s, i - 1).glass).bound_radius;
    EXPECT_GT(gap, 0.01) << i;
  }
  EXPECT_TRUE(s.params.camera.auto_frame) << "the camera frames the whole flight";
}

// What the viewer's Save and the page's Export write: the whole scene, loading back to
// the same objects, placements and values.
TEST(ScenePreset, WrittenSceneLoadsBackTheSame) {
  Scene s = resolve_scene_objects({"flight", "", {"objects[2].liquid.fill=0.4", "env.floor=false"}, {}});
  s.objects[1].placement.yaw = 15.0f;
  const fs::path file = fs::temp_directory_path() / ("draught-scene-" + std::to_string(::getpid()) + ".json");
  save_preset(file, scene_preset_json(s, "my-flight", "saved in a test"));
  const Scene back = resolve_scene_objects({file.string(), "", {}, {}});
  fs::remove(file);
  ASSERT_EQ(back.objects.size(), s.objects.size());
  for (size_t i = 0; i < s.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].name, s.objects[i].name);
    EXPECT_EQ(back.objects[i].placement.position, s.objects[i].placement.position);
    EXPECT_EQ(back.objects[i].placement.yaw, s.objects[i].placement.yaw);
    for (const ParamDesc& d : param_table()) {
      if (d.scope == ParamScope::Vessel) {
        EXPECT_TRUE(get_param(vessel_document(back, int(i)), d) == get_param(vessel_document(s, int(i)), d))
            << "objects[" << i << "]." << d.path;
      }
    }
  }
  EXPECT_FLOAT_EQ(vessel_document(back, 2).liquid.fill, 0.4f);
  EXPECT_FALSE(back.params.env.floor);
}

// Saved files carry the shortest text of each value, not float noise (0.65, not
// 0.6499999761581421), and it reads back as the same float.
TEST(ScenePreset, SavedValuesAreShortestText) {
  Params p = default_params();
  p.liquid.fill = 0.65f;
  p.light.direction = glm::vec3(-0.55f, 0.75f, 0.45f);
  const std::string text = preset_json(p, "scene", "short", "", {});
  EXPECT_NE(text.find("\"fill\": 0.65"), std::string::npos) << text;
  EXPECT_EQ(text.find("0.6499999"), std::string::npos);
  EXPECT_EQ(text.find("0.550000"), std::string::npos);
  EXPECT_NE(text.find("-0.55"), std::string::npos);
  Params back = default_params();
  apply_preset(parse_preset(text, "short.json"), back);
  EXPECT_EQ(back.liquid.fill, p.liquid.fill);
  EXPECT_EQ(back.light.direction, p.light.direction);
  EXPECT_EQ(shortest_double(0.1f), 0.1);
  for (float v : {0.0f, 1e-7f, 0.3f, 1.52f, 1500.0f, 36000.0f, 3.4e38f}) EXPECT_EQ(float(shortest_double(v)), v) << v;
}

TEST(ScenePreset, ObjectParamsComeAfterGlassAndDrink) {
  const Scene s = scene_from_preset(parse_preset(
      scene_json(R"([{ "name": "x", "glass": "pint", "drink": "lager",
                       "params": { "liquid": { "fill": 0.3 }, "glass": { "ior": 1.6 }, "clip": { "enabled": true } } }])"),
      "s.json"));
  const VesselParams v = vessel_of(s, 0);
  EXPECT_EQ(v.liquid.fill, 0.3f);
  EXPECT_EQ(v.glass.ior, 1.6f);
  EXPECT_TRUE(v.clip.enabled);
  EXPECT_EQ(v.liquid.srm, 3.5f) << "the lager's colour";
}

TEST(ScenePreset, GlassDefaultsToTheDrinksSuggestionAndDrinkToTheTable) {
  const Scene s = scene_from_preset(parse_preset(scene_json(R"([
      { "name": "stout", "drink": "stout" },
      { "name": "empty", "glass": "wine", "position": [0.2, 0, 0] } ])"), "s.json"));
  EXPECT_TRUE(same_vessel(vessel_of(s, 0), resolve_scene({"stout", "", {}, {}}))) << "stout in its nonic";
  Params wine_glass = default_params();
  apply_preset(load_preset(find_preset("wine", "glass")), wine_glass);
  EXPECT_TRUE(same_vessel(vessel_of(s, 1), wine_glass)) << "the table's drink in a wine glass";
}

TEST(ScenePreset, ObjectPresetByPathRelativeToTheSceneFile) {
  const fs::path dir = fs::temp_directory_path() / ("draught-scene-" + std::to_string(::getpid()));
  fs::create_directories(dir / "mine");
  write_file_atomic(dir / "mine" / "g.json", R"({ "kind": "glass", "name": "g", "params": { "glass": { "ior": 1.7 } } })");
  write_file_atomic(dir / "scene.json", scene_json(R"([{ "name": "x", "glass": "mine/g.json", "drink": "lager" }])"));
  const Scene s = scene_from_preset(load_preset(dir / "scene.json"));
  EXPECT_EQ(vessel_of(s, 0).glass.ior, 1.7f);
  fs::remove_all(dir);
}

TEST(ScenePreset, AtTheLimitOfObjects) {
  // kMaxSceneObjects pints on a grid 12 cm apart: accepted, one more refused.
  auto grid = [](int n) {
    std::string objects = "[";
    for (int i = 0; i < n; ++i) {
      char buf[160];
      std::snprintf(buf, sizeof buf, R"(%s{ "name": "g%d", "glass": "pint", "drink": "lager", "position": [%g, 0, %g] })",
                    i ? ", " : "", i, -0.5 + 0.12 * (i % 9), -0.5 + 0.12 * (i / 9));
      objects += buf;
    }
    return objects + "]";
  };
  const Scene s = scene_from_preset(parse_preset(scene_json(grid(kMaxSceneObjects)), "s.json"));
  EXPECT_EQ(int(s.objects.size()), kMaxSceneObjects);
  EXPECT_TRUE(has(scene_parse_error(scene_json(grid(kMaxSceneObjects + 1))),
                  {"s.json", "field 'objects'", "at most " + std::to_string(kMaxSceneObjects), "got 65"}));
}

// ------------------------------------------------------------ every error --

TEST(ScenePresetErrors, ObjectsMustBeANonEmptyArrayOfObjects) {
  EXPECT_TRUE(has(scene_parse_error(scene_json("{}")), {"s.json", "field 'objects'", "expected an array"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json("[]")), {"s.json", "field 'objects'", "expected an array of 1 to 64"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json("[1]")), {"s.json", "field 'objects[0]'", "expected an object"}));
}

TEST(ScenePresetErrors, OnlyScenesPlaceObjects) {
  const std::string m = scene_parse_error(R"({ "kind": "drink", "name": "d", "objects": [{ "name": "a" }] })");
  EXPECT_TRUE(has(m, {"s.json", "field 'objects'", "only a scene preset places objects"}));
}

TEST(ScenePresetErrors, ObjectFields) {
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "glass": "pint" }])")), {"s.json", "objects[0].name", "missing"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "" }])")), {"objects[0].name", "non-empty string"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": 3 }])")), {"objects[0].name", "string", "got 3"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "drink": ["lager"] }])")), {"objects[0].drink", "string"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "glas": "pint" }])")),
                  {"objects[0].glas", "unknown key", "expected one of name, kind, glass, drink, position, yaw, params, droplets"}));
  // A droplets object: its own parameters, no glass; one per scene.
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "d", "kind": "droplets", "glass": "pint" }])")),
                  {"objects[0].glass", "a droplets object has no glass"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "d", "kind": "drops" }])")),
                  {"objects[0].kind", "expected \"vessel\" (the default), \"droplets\" or \"pointcloud\"", "\"drops\""}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "d", "kind": "droplets", "droplets": { "blend": -1 } }])")),
                  {"objects[0].droplets.blend", "expected a number in [0, 0.2] (m)", "got -1"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "d", "kind": "droplets" }, { "name": "e", "kind": "droplets" }])")),
                  {"objects[1].kind", "at most one droplets object"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a" }, { "name": "b", "position": [0, 0] }])")),
                  {"s.json", "objects[1].position", "[x, y, z]"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "position": [7, 0, 0] }])")),
                  {"objects[0].position", "x and z in [-5, 5]", "got [7,0,0]"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "position": [0, -0.1, 0] }])")),
                  {"objects[0].position", "y (the foot above the floor) in [0, 1]"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "position": [0, "0", 0] }])")), {"objects[0].position"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "yaw": 400 }])")), {"objects[0].yaw", "[-360, 360]", "400"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "params": 1 }])")), {"objects[0].params", "groups"}));
}

TEST(ScenePresetErrors, NamesAreUnique) {
  const std::string m = scene_parse_error(scene_json(R"([{ "name": "a" }, { "name": "b" }, { "name": "a" }])"));
  EXPECT_TRUE(has(m, {"s.json", "objects[2].name", "no other object has", "\"a\"", "objects[0]"}));
}

TEST(ScenePresetErrors, ObjectParamsAreValidated) {
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "params": { "liquid": { "fill": 2 } } }])")),
                  {"s.json", "field 'objects[0].params.liquid.fill'", "[0, 0.98]", "got 2"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "params": { "liquid": { "fil": 0.5 } } }])")),
                  {"objects[0].params.liquid.fil", "did you mean 'liquid.fill'"}));
}

TEST(ScenePresetErrors, SceneGroupsInsideAnObjectAreRefused) {
  const std::string m = scene_parse_error(scene_json(R"([{ "name": "a" }, { "name": "b", "params": { "env": { "floor": false } } }])"));
  EXPECT_TRUE(has(m, {"s.json", "field 'objects[1].params.env.floor'", "belongs to the whole scene", "top-level"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a", "params": { "camera": { "vfov": 30 } } }])")),
                  {"objects[0].params.camera.vfov", "whole scene"}));
}

TEST(ScenePresetErrors, VesselGroupsAtTheTopOfASceneWithObjectsAreRefused) {
  const std::string m = scene_parse_error(scene_json(R"([{ "name": "a" }])", R"({ "liquid": { "fill": 0.5 } })"));
  EXPECT_TRUE(has(m, {"s.json", "field 'params.liquid.fill'", "per object", "objects[N].params", "env.*"}));
  EXPECT_TRUE(has(scene_parse_error(scene_json(R"([{ "name": "a" }])", "{}", R"("suggested_glass": "pint", )")),
                  {"s.json", "suggested_glass", "objects[N].glass"}));
}

TEST(ScenePresetErrors, GlassAndDrinkNamesMustExist) {
  const std::string drink = scene_error(scene_json(R"([
      { "name": "a", "drink": "lager" }, { "name": "b", "drink": "lager", "position": [0.2, 0, 0] },
      { "name": "c", "drink": "stuot", "position": [0.4, 0, 0] } ])"));
  EXPECT_TRUE(has(drink, {"s.json", "field 'objects[2].drink'", "expected one of", "amber-ale", "hefeweizen",
                          "got \"stuot\"", "did you mean \"stout\"?"}));
  const std::string glass = scene_error(scene_json(R"([{ "name": "a", "glass": "tumbler", "drink": "lager" }])"));
  EXPECT_TRUE(has(glass, {"s.json", "field 'objects[0].glass'", "expected one of", "flute", "weizen", "\"tumbler\""}));
  EXPECT_EQ(glass.find("did you mean"), std::string::npos) << "nothing is near 'tumbler': " << glass;
  // A drink's name as a glass is not a glass.
  EXPECT_TRUE(has(scene_error(scene_json(R"([{ "name": "a", "glass": "lager" }])")),
                  {"objects[0].glass", "expected one of", "got \"lager\""}));
  // A path to a file of the wrong kind.
  const std::string kind = scene_error(
      scene_json(R"([{ "name": "a", "glass": ")" + (test::preset_source_dir() / "drinks" / "lager.json").string() + R"(" }])"));
  EXPECT_TRUE(has(kind, {"s.json", "objects[0].glass", "expected a glass preset", "lager.json is a drink preset"}));
  EXPECT_TRUE(has(scene_error(scene_json(R"([{ "name": "a", "drink": "nowhere/x.json" }])")),
                  {"s.json", "objects[0].drink", "no such drink preset file"}));
  // A NUL in a name would cut the path short at the folder (found by the mutation fuzzer).
  EXPECT_TRUE(has(scene_error(scene_json(R"([{ "name": "a", "glass": "\u0000pint" }])")),
                  {"s.json", "objects[0].glass", "expected a glass preset's name or path", "\\u0000pint"}));
}

TEST(ScenePresetErrors, OverlappingGlassesNameBothObjects) {
  const std::string m = scene_error(scene_json(R"([
      { "name": "left", "glass": "pint", "drink": "lager", "position": [0, 0, 0] },
      { "name": "far", "glass": "pint", "drink": "lager", "position": [0.5, 0, 0] },
      { "name": "right", "glass": "nonic", "drink": "stout", "position": [0.06, 0, 0] } ])"));
  EXPECT_TRUE(has(m, {"s.json", "objects[0] 'left'", "objects[2] 'right'", "overlap", "interpenetrate", "0.060 m"}));
  // Touching exactly is allowed; a millimetre closer is not.
  const double r = build_vessel(test::params_with_glass("pint").glass).bound_radius;
  char objects[256];
  std::snprintf(objects, sizeof objects, R"([{ "name": "a", "glass": "pint" }, { "name": "b", "glass": "pint", "position": [%.6f, 0, 0] }])",
                2 * r + 1e-5);
  EXPECT_EQ(scene_error(scene_json(objects)), "no error");
  std::snprintf(objects, sizeof objects, R"([{ "name": "a", "glass": "pint" }, { "name": "b", "glass": "pint", "position": [0, 0, %.6f] }])",
                2 * r - 1e-3);
  EXPECT_TRUE(has(scene_error(scene_json(objects)), {"objects[0] 'a'", "objects[1] 'b'", "overlap"}));
  // An object's own glass parameters count: a wider profile makes it overlap.
  EXPECT_TRUE(has(scene_error(scene_json(R"([
      { "name": "a", "glass": "pint", "position": [-0.06, 0, 0] },
      { "name": "b", "glass": "pint", "position": [0.06, 0, 0],
        "params": { "glass": { "profile": [[0.03, 0], [0.09, 0.15]] } } } ])")),
                  {"objects[0] 'a'", "objects[1] 'b'", "overlap"}));
}

// ------------------------------------------------------------- resolving --

TEST(ResolveSceneObjects, SingleGlassPresetIsOneObjectExactlyAsResolveScene) {
  for (const SceneRequest& req : {SceneRequest{"lager", "", {}, {}}, SceneRequest{"stout", "tulip", {"liquid.fill=0.5"}, {}},
                                  SceneRequest{"packshot-lager", "", {}, {"eye=0,0.3,0.2"}},
                                  SceneRequest{"red-wine", "", {"env.floor=false", "glass.ior=1.6"}, {"vfov=30"}}}) {
    const Scene s = resolve_scene_objects(req);
    ASSERT_EQ(s.objects.size(), 1u);
    EXPECT_EQ(s.objects[0].placement.position, glm::vec3(0.0f));
    const Params p = resolve_scene(req);
    const Params back = vessel_document(s, 0);
    for (const auto& d : param_table()) EXPECT_TRUE(get_param(back, d) == get_param(p, d)) << req.preset << " " << d.path;
  }
  // And the values are what the presets and overrides say.
  const Params p = resolve_scene({"stout", "tulip", {"liquid.fill=0.5"}, {}});
  EXPECT_EQ(p.liquid.fill, 0.5f);
  EXPECT_EQ(p.liquid.srm, 40.0f);
  EXPECT_EQ(p.glass.profile, test::params_with_glass("tulip").glass.profile);
}

TEST(ResolveSceneObjects, FlightWithSetsOnOneObjectOrAll) {
  Scene s = resolve_scene_objects({"flight", "", {"objects[2].liquid.fill=0.5", "env.floor=false"}, {"vfov=30"}});
  ASSERT_EQ(s.objects.size(), 4u);
  const float pilsner_fill = resolve_scene({"pilsner", "", {}, {}}).liquid.fill;
  EXPECT_EQ(vessel_of(s, 0).liquid.fill, pilsner_fill);
  EXPECT_EQ(vessel_of(s, 2).liquid.fill, 0.5f);
  EXPECT_FALSE(s.params.env.floor);
  EXPECT_EQ(s.params.camera.vfov, 30.0f);
  s = resolve_scene_objects({"flight", "", {"liquid.fill=0.45"}, {}});
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(vessel_of(s, i).liquid.fill, 0.45f) << i;
  // The first object's document for single-glass callers.
  EXPECT_EQ(resolve_scene({"flight", "", {}, {}}).liquid.fill, pilsner_fill);
  std::string log;
  resolve_scene_objects({"flight", "", {}, {}}, &log);
  EXPECT_TRUE(has(log, {"flight.json", "4 objects", "objects[2] stout: glass nonic", "stout.json"}));
}

std::string resolve_error(const SceneRequest& req) {
  return test::input_error_of([&] { resolve_scene_objects(req); });
}

TEST(ResolveSceneObjects, Errors) {
  EXPECT_TRUE(has(resolve_error({"flight", "", {"objects[9].liquid.fill=0.5"}, {}}),
                  {"--set objects[9].liquid.fill=0.5", "field 'objects[9].liquid.fill'", "from 0 to 3", "4 objects"}));
  EXPECT_TRUE(has(resolve_error({"lager", "", {"objects[1].liquid.fill=0.5"}, {}}), {"from 0 to 0"}));
  EXPECT_TRUE(has(resolve_error({"flight", "", {"objects[1].env.floor=false"}, {}}),
                  {"--set objects[1].env.floor=false", "belongs to the whole scene"}));
  EXPECT_TRUE(has(resolve_error({"flight", "", {"objects[1].liquid.fil=0.5"}, {}}),
                  {"--set objects[1].liquid.fil=0.5", "unknown parameter 'liquid.fil'", "did you mean 'liquid.fill'"}));
  EXPECT_TRUE(has(resolve_error({"flight", "", {"objects[1].liquid.fill=7"}, {}}),
                  {"--set objects[1].liquid.fill=7", "field 'objects[1].liquid.fill'", "[0, 0.98]", "\"7\""}));
  EXPECT_TRUE(has(resolve_error({"flight", "", {"objects[one].liquid.fill=0.5"}, {}}), {"objects[2].liquid.fill"}));
  EXPECT_TRUE(has(resolve_error({"flight", "pint", {}, {}}), {"--glass pint", "flight", "places its own glasses"}));
  // A --set that makes two glasses interpenetrate.
  EXPECT_TRUE(has(resolve_error({"flight", "", {"objects[1].glass.profile=0.03,0;0.1,0.15"}, {}}),
                  {"--set", "objects[0] 'pilsner'", "objects[1] 'amber-ale'", "overlap"}));
  // Unchanged messages for single glasses.
  EXPECT_TRUE(has(resolve_error({"lager", "", {"liquid.fill=7"}, {}}),
                  {"--set liquid.fill=7: field 'liquid.fill': expected a number in [0, 0.98], got \"7\""}));
}

TEST(ShippedPresets, ScenesLoadAndResolve) {
  for (auto& e : fs::directory_iterator(test::preset_source_dir() / "scenes")) {
    if (e.path().extension() != ".json") continue;
    const Preset p = load_preset(e.path());
    EXPECT_EQ(p.kind, "scene") << e.path();
    EXPECT_EQ(p.name, e.path().stem().string()) << e.path();
    const Scene s = resolve_scene_objects({p.name, "", {}, {}});
    EXPECT_EQ(s.objects.size(), p.objects.empty() ? 1u : p.objects.size()) << e.path();
  }
}

}  // namespace
}  // namespace draught
