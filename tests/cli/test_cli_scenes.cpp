// End-to-end tests of scenes of several objects: `render --preset flight`, --set on one
// object, the errors (exit 1, the flag or file and field named, nothing written),
// `validate` of scene presets and of timelines that address objects, `presets` and
// `params` showing objects and scopes, and animations of a scene.
#include "cli_helpers.hpp"

#include "core/io/image.hpp"


namespace draught_cli_test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

const std::string kFlight = (kSourceDir / "presets/scenes/flight.json").string();

using Scenes = CliTest;

// ---------------------------------------------------------------- render

TEST_F(Scenes, RenderFlightWritesAPng) {
  const fs::path png = out() / "x.png";
  auto r = render({"--preset", "flight", "-o", png.string(), "--verbose"}, "64x40");
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "wrote " + png.string())) << r.describe();
  const PngInfo info = png_info(png);
  EXPECT_EQ(info.error, "");
  EXPECT_EQ(info.width, 64u);
  EXPECT_EQ(info.height, 40u);
  // --verbose names the scene and every object's glass and drink.
  for (const char* s : {"flight.json", "4 objects", "objects[0] pilsner", "objects[1] amber-ale: glass tulip",
                        "objects[2] stout: glass nonic", "objects[3] hefeweizen: glass weizen", "hefeweizen.json"})
    EXPECT_TRUE(contains(r.err, s)) << s << "\n" << r.describe();
}

TEST_F(Scenes, SetOnOneObjectIsAcceptedAndChangesThePicture) {
  const fs::path a = out() / "a.png", b = out() / "b.png", c = out() / "c.png";
  ASSERT_EQ(render({"--preset", "flight", "-o", a.string()}).exit_code, 0);
  auto r = render({"--preset", "flight", "--set", "objects[2].liquid.fill=0.5", "-o", b.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(b).error, "");
  // The first glass is drawn by every renderer: emptying it changes the picture.
  r = render({"--preset", "flight", "--set", "objects[0].liquid.fill=0", "-o", c.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_NE(read_file(a), read_file(c)) << "objects[0].liquid.fill=0 changed nothing";
  // A path without the prefix sets every object.
  r = render({"--preset", "flight", "--set", "liquid.fill=0.3", "-o", (out() / "d.png").string()});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
}

TEST_F(Scenes, ObjectIndexOutOfRangeIsRefused) {
  auto r = render({"--preset", "flight", "--set", "objects[9].liquid.fill=0.5", "-o", (out() / "x.png").string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"--set objects[9].liquid.fill=0.5", "field 'objects[9].liquid.fill'",
                     "an object index from 0 to 3", "the scene has 4 objects"});
}

TEST_F(Scenes, OtherBadObjectPathsAreRefused) {
  expect_failure(render({"--preset", "flight", "--set", "objects[1].env.floor=false", "-o", (out() / "x.png").string()}),
                 {"--set objects[1].env.floor=false", "belongs to the whole scene"});
  expect_failure(render({"--preset", "flight", "--set", "objects[1].liquid.fil=0.5", "-o", (out() / "x.png").string()}),
                 {"--set objects[1].liquid.fil=0.5", "did you mean 'liquid.fill'"});
  expect_failure(render({"--preset", "flight", "--set", "objects[1].liquid.fill=2", "-o", (out() / "x.png").string()}),
                 {"field 'objects[1].liquid.fill'", "[0, 0.98]"});
  // A single glass has object 0 only.
  expect_failure(render({"--preset", "lager", "--set", "objects[1].liquid.fill=0.5", "-o", (out() / "x.png").string()}),
                 {"from 0 to 0"});
}

TEST_F(Scenes, GlassFlagOnASceneWithObjectsIsRefused) {
  auto r = render({"--preset", "flight", "--glass", "pint", "-o", (out() / "x.png").string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"--glass pint", "flight", "places its own glasses"});
}

TEST_F(Scenes, SceneFileOfYourOwn) {
  const fs::path f = in() / "pair.json";
  write_file(f, R"({ "draught_preset": 1, "kind": "scene", "name": "pair", "params": { "env": { "floor": false } },
    "objects": [ { "name": "left", "glass": "pint", "drink": "lager", "position": [-0.06, 0, 0] },
                 { "name": "right", "glass": "wine", "drink": "red-wine", "position": [0.06, 0, 0], "yaw": 45 } ] })");
  auto r = render({"--preset", f.string(), "-o", (out() / "pair.png").string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(png_info(out() / "pair.png").error, "");
}

// ---------------------------------------------------------------- validate

TEST_F(Scenes, ValidateFlight) {
  auto r = draught({"validate", kFlight});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, kFlight + ": ok (scene 'flight', 4 objects")) << r.describe();
  EXPECT_EQ(r.err, "");
}

TEST_F(Scenes, ValidateReportsBadScenesWithFileAndField) {
  const fs::path overlap = in() / "overlap.json", drink = in() / "drink.json", scope = in() / "scope.json";
  write_file(overlap, R"({ "kind": "scene", "name": "o", "objects": [
      { "name": "a", "glass": "pint", "drink": "lager" },
      { "name": "b", "glass": "nonic", "drink": "stout", "position": [0.05, 0, 0] } ] })");
  write_file(drink, R"({ "kind": "scene", "name": "d", "objects": [
      { "name": "a", "drink": "lager" }, { "name": "b", "drink": "lagr", "position": [0.3, 0, 0] } ] })");
  write_file(scope, R"({ "kind": "scene", "name": "s", "objects": [
      { "name": "a", "drink": "lager", "params": { "light": { "power": 3 } } } ] })");
  auto r = draught({"validate", overlap.string(), drink.string(), scope.string(), kFlight});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, overlap.string() + ": objects[0] 'a' and objects[1] 'b' overlap")) << r.describe();
  EXPECT_TRUE(contains(r.err, drink.string() + ": field 'objects[1].drink': expected one of")) << r.describe();
  EXPECT_TRUE(contains(r.err, "(did you mean \"lager\"?)")) << r.describe();
  EXPECT_TRUE(contains(r.err, scope.string() + ": field 'objects[0].params.light.power'")) << r.describe();
  EXPECT_TRUE(contains(r.out, kFlight + ": ok")) << "the good file is still checked\n" << r.describe();
}

TEST_F(Scenes, ValidateTimelinesThatAddressObjects) {
  const fs::path good = in() / "good.json", bad = in() / "bad.json", range = in() / "range.json";
  write_file(good, R"({ "draught_timeline": 1, "name": "g", "preset": "flight", "actions": [
      { "at": 0, "action": "tilt", "angle": 20, "duration": 1, "object": "stout" },
      { "at": 0, "action": "set", "param": "objects[3].liquid.haze", "value": 50 },
      { "at": 1, "action": "sip", "amount": 0.1, "object": 1 } ] })");
  write_file(bad, R"({ "draught_timeline": 1, "name": "b", "preset": "flight", "actions": [
      { "at": 0, "action": "pour" }, { "at": 0, "action": "pour" }, { "at": 0, "action": "pour" },
      { "at": 0, "action": "tilt", "angle": 20, "object": "stuot" } ] })");
  write_file(range, R"({ "draught_timeline": 1, "name": "r", "preset": "lager", "actions": [
      { "at": 0, "action": "sip", "amount": 0.1, "object": 2 } ] })");
  auto r = draught({"validate", good.string()});
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, good.string() + ": ok (timeline 'g', 3 actions")) << r.describe();
  r = draught({"validate", bad.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, bad.string() + ": field 'actions[3].object'")) << r.describe();
  EXPECT_TRUE(contains(r.err, "did you mean \"stout\"?")) << r.describe();
  r = draught({"validate", range.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, range.string() + ": field 'actions[0].object'")) << r.describe();
  EXPECT_TRUE(contains(r.err, "from 0 to 0")) << r.describe();
}

// ---------------------------------------------------------------- listings

TEST_F(Scenes, PresetsListsTheFlightWithItsObjectCount) {
  auto r = draught({"presets"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  bool found = false;
  for (auto& line : lines_of(r.out)) {
    std::istringstream ls(line);
    std::string kind, name, glass, objects;
    ls >> kind >> name >> glass >> objects;
    if (name == "flight") {
      found = true;
      EXPECT_EQ(kind, "scene");
      EXPECT_EQ(objects, "4") << line;
    }
    if (name == "packshot-lager") { EXPECT_EQ(objects, "1") << line; }
    if (kind == "drink") { EXPECT_EQ(objects, "-") << line; }
  }
  EXPECT_TRUE(found) << r.out;
  EXPECT_TRUE(contains(lines_of(r.out).at(0), "objects")) << r.out;
}

TEST_F(Scenes, ParamsShowEachParametersScope) {
  auto r = draught({"params"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  std::map<std::string, std::string> rows;
  for (auto& line : lines_of(r.out)) rows[line.substr(0, line.find(' '))] = line;
  EXPECT_TRUE(matches(rows["liquid.fill"], R"(\[0, 0\.98\]\s+object\s)")) << rows["liquid.fill"];
  EXPECT_TRUE(matches(rows["glass.profile"], R"(\s+m\s+object\s)")) << rows["glass.profile"];
  EXPECT_TRUE(matches(rows["env.floor"], R"(\s+scene\s)")) << rows["env.floor"];
  EXPECT_TRUE(matches(rows["camera.vfov"], R"(deg\s+scene\s)")) << rows["camera.vfov"];
  r = draught({"params", "--markdown"});
  EXPECT_TRUE(contains(r.out, "| unit | scope | description |")) << r.out;
  EXPECT_TRUE(contains(r.out, "| `liquid.fill` | float | `0.85` | [0, 0.98] |  | per object |")) << r.out;
  EXPECT_TRUE(contains(r.out, "| `render.tonemap` | enum | `aces` | none|aces |  | scene |")) << r.out;
  // docs/PRESETS.md explains the objects[N]. form.
  const std::string docs = read_file(kSourceDir / "docs/PRESETS.md");
  EXPECT_TRUE(contains(docs, "objects[2].liquid.fill")) << "docs/PRESETS.md does not document objects[N].";
}

// ---------------------------------------------------------------- animations

TEST_F(Scenes, TimelineOnAScene) {
  const fs::path tl = in() / "flight-tilt.json";
  write_file(tl, R"({ "draught_timeline": 1, "name": "flight-tilt", "preset": "flight", "duration": 1, "actions": [
      { "at": 0, "action": "tilt", "angle": 30, "duration": 0.5, "object": "pilsner" },
      { "at": 0, "action": "sip", "amount": 0.3, "duration": 0.5, "object": 3 } ] })");
  const std::string dir = (out() / "frames").string() + "/";
  auto r = draught({"render", "--timeline", tl.string(), "--size", "40x24", "--fps", "3", "--supersample", "1", "-o", dir});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "frames")), "frame_00000.png, frame_00001.png, frame_00002.png");
  EXPECT_TRUE(contains(r.out, "spilled")) << r.describe();
  // The first glass tips: the frames differ.
  EXPECT_NE(read_file(out() / "frames/frame_00000.png"), read_file(out() / "frames/frame_00002.png"));
  // A timeline naming an object the scene does not have is refused before anything is written.
  write_file(tl, R"({ "draught_timeline": 1, "name": "flight-tilt", "preset": "flight", "duration": 1, "actions": [
      { "at": 0, "action": "tilt", "angle": 30, "object": "cider" } ] })");
  fs::remove_all(out() / "frames");
  r = draught({"render", "--timeline", tl.string(), "--size", "40x24", "--fps", "3", "-o", dir});
  expect_failure(r, {tl.string(), "actions[0].object", "\"cider\""});
}

TEST_F(Scenes, ShippedTimelineOnTheFlight) {
  // A single-glass timeline (no objects) drives every glass of the scene alike.
  auto r = draught({"render", "--timeline", "gentle-tilt", "--preset", "flight", "--size", "32x20", "--fps", "2",
                    "--duration", "1", "--supersample", "1", "-o", (out() / "f").string() + "/"});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "f")), "frame_00000.png, frame_00001.png");
}

}  // namespace
}  // namespace draught_cli_test
