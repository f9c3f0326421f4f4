// The viewer's editor without a window: undo steps, presets, load/save errors that leave
// everything as it was, and scenes of several objects with a selection.
#include "editor.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

namespace draught::viewer {
namespace {

namespace fs = std::filesystem;

// Every parameter as text: equal texts, equal parameters.
std::string dump(const Params& p) { return preset_json(p, "scene", "x", "", {}); }

// The scene with liquid.fill set on every object (the one object of a single-glass scene).
Scene with_fill(Scene s, float fill) {
  set_param(s, parse_param_ref(s, "liquid.fill"), fill);
  return s;
}

class EditorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("draught-viewer-test-" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(EditorTest, OpensLikeTheCli) {
  Editor ed("lager", "");
  EXPECT_EQ(ed.drink_label(), "lager");
  EXPECT_EQ(ed.glass_label(), "pint");  // the drink's suggested glass
  EXPECT_EQ(dump(ed.document()), dump(resolve_scene({"lager", "", {}, {}})));
  EXPECT_THROW(Editor("no-such-drink", ""), InputError);
}

TEST_F(EditorTest, UndoStepsBackOneChangeAtATime) {
  Editor ed("lager", "");
  const std::string original = dump(ed.document());
  EXPECT_FALSE(ed.undo());
  ed.change(with_fill(ed.scene(), 0.5f));
  ed.settle(false);
  ed.change(with_fill(ed.scene(), 0.3f));
  ed.settle(false);
  EXPECT_EQ(ed.undo_depth(), 2u);
  const unsigned rev = ed.revision();
  ASSERT_TRUE(ed.undo());
  EXPECT_GT(ed.revision(), rev);  // the app hands the old parameters to the simulation
  EXPECT_FLOAT_EQ(ed.document().liquid.fill, 0.5f);
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(dump(ed.document()), original);
  EXPECT_FALSE(ed.undo());
}

TEST_F(EditorTest, ADragIsOneUndoStep) {
  Editor ed("lager", "");
  const std::string original = dump(ed.document());
  for (float f : {0.7f, 0.6f, 0.5f}) {
    ed.change(with_fill(ed.scene(), f));
    ed.settle(true);  // the slider is still held
  }
  ed.settle(false);
  EXPECT_EQ(ed.undo_depth(), 1u);
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(dump(ed.document()), original);
}

TEST_F(EditorTest, ChoosingADrinkBringsItsGlassAndCanBeUndone) {
  Editor ed("lager", "");
  const std::string lager = dump(ed.document());
  ASSERT_TRUE(ed.choose_drink("stout")) << ed.status().text;
  EXPECT_EQ(ed.drink_label(), "stout");
  EXPECT_EQ(ed.glass_label(), "nonic");
  ASSERT_TRUE(ed.choose_glass("tulip")) << ed.status().text;
  EXPECT_EQ(ed.glass_label(), "tulip");
  EXPECT_EQ(dump(ed.document()), dump(resolve_scene({"stout", "tulip", {}, {}})));
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(ed.glass_label(), "nonic");  // the names come back with the parameters
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(dump(ed.document()), lager);
  EXPECT_EQ(ed.drink_label(), "lager");
  EXPECT_EQ(ed.glass_label(), "pint");
  ASSERT_TRUE(ed.choose_glass("flute"));  // undone back to lager: the glass goes with lager
  EXPECT_EQ(dump(ed.document()), dump(resolve_scene({"lager", "flute", {}, {}})));
}

TEST_F(EditorTest, BadFilesChangeNothing) {
  Editor ed("lager", "");
  ed.change(with_fill(ed.scene(), 0.4f));
  ed.settle(false);
  const std::string before = dump(ed.document());
  const unsigned rev = ed.revision();

  EXPECT_FALSE(ed.load((dir / "missing.json").string()));
  EXPECT_TRUE(ed.status().error);
  EXPECT_NE(ed.status().text.find("missing.json"), std::string::npos) << ed.status().text;

  write_file_atomic(dir / "broken.json", "{ \"draught_preset\": 1, \"kind\": \"drink\", ");
  EXPECT_FALSE(ed.load((dir / "broken.json").string()));
  EXPECT_NE(ed.status().text.find("broken.json"), std::string::npos) << ed.status().text;

  write_file_atomic(dir / "bad-value.json",
                    R"({ "draught_preset": 1, "kind": "drink", "name": "x", "params": { "liquid": { "fill": 7 } } })");
  EXPECT_FALSE(ed.load((dir / "bad-value.json").string()));
  EXPECT_NE(ed.status().text.find("liquid.fill"), std::string::npos) << ed.status().text;

  EXPECT_FALSE(ed.choose_glass("no-such-glass"));
  EXPECT_FALSE(ed.save_as((dir / "no-such-dir" / "x.json").string(), "scene"));
  EXPECT_FALSE(ed.save());  // nothing loaded or saved yet
  EXPECT_EQ(dump(ed.document()), before);
  EXPECT_EQ(ed.revision(), rev);
  EXPECT_EQ(ed.drink_label(), "lager");
}

TEST_F(EditorTest, SavedScenesLoadBackTheSame) {
  Editor ed("red-wine", "");
  ed.change(with_fill(ed.scene(), 0.33f));
  ed.settle(false);
  const std::string edited = dump(ed.document());
  const fs::path file = dir / "mine.json";
  ASSERT_TRUE(ed.save_as(file.string(), "scene")) << ed.status().text;
  EXPECT_EQ(ed.file(), file.string());
  EXPECT_EQ(load_preset(file).kind, "scene");

  Editor other("lager", "");
  ASSERT_TRUE(other.load(file.string())) << other.status().text;
  EXPECT_EQ(dump(other.document()), edited);
  EXPECT_EQ(other.drink_label(), "mine");
  EXPECT_EQ(other.glass_label(), "(the scene's)");
  ASSERT_TRUE(other.save()) << other.status().text;  // Save writes the loaded file again
  EXPECT_EQ(load_preset(file).kind, "scene");
}

TEST_F(EditorTest, GlassAndDrinkFilesPlayTheirRole) {
  Editor ed("lager", "");
  ASSERT_TRUE(ed.choose_glass("weizen"));
  const fs::path glass = dir / "my-glass.json";
  ASSERT_TRUE(ed.save_as(glass.string(), "glass")) << ed.status().text;
  EXPECT_EQ(load_preset(glass).kind, "glass");
  ASSERT_TRUE(ed.choose_drink("stout"));  // into a nonic
  ASSERT_TRUE(ed.load(glass.string())) << ed.status().text;
  EXPECT_EQ(ed.glass_label(), "my-glass");
  EXPECT_EQ(ed.drink_label(), "stout");
  EXPECT_EQ(dump(ed.document()), dump(resolve_scene({"stout", glass.string(), {}, {}})));
}

// Two lagers side by side: the scene of several objects a scene preset would give.
Scene two_glasses(const Scene& one) {
  Scene s = one;
  SceneObject second = s.objects.at(0);
  second.name = "second";
  second.placement.position.x = 0.12f;
  s.objects.push_back(second);
  return s;
}

TEST_F(EditorTest, SingleGlassPresetsAreSceneOfOneObject) {
  Editor ed("stout", "");
  ASSERT_EQ(ed.scene().objects.size(), 1u);
  EXPECT_EQ(ed.selected(), 0);
  EXPECT_EQ(dump(ed.document()), dump(vessel_document(resolve_scene_objects({"stout", "", {}, {}}), 0)));
}

TEST_F(EditorTest, SelectionIsNoUndoStepAndStaysInRange) {
  Editor ed("lager", "");
  ed.change(two_glasses(ed.scene()));
  ed.settle(false);
  const unsigned rev = ed.revision();
  const std::size_t depth = ed.undo_depth();
  ed.select(1);
  EXPECT_EQ(ed.selected(), 1);
  EXPECT_EQ(ed.scene().selected, 1);
  EXPECT_EQ(ed.revision(), rev);  // nothing to hand on: the simulation is told directly
  EXPECT_EQ(ed.undo_depth(), depth);
  ed.select(7);
  EXPECT_EQ(ed.selected(), 1);  // the last object
  ed.select(-3);
  EXPECT_EQ(ed.selected(), 0);

  ed.select(1);
  ed.change(with_fill(ed.scene(), 0.5f));  // an edit keeps the selection
  ed.settle(false);
  EXPECT_EQ(ed.selected(), 1);
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(ed.selected(), 1);
  ASSERT_TRUE(ed.undo());  // back to one glass: the selection follows
  EXPECT_EQ(ed.scene().objects.size(), 1u);
  EXPECT_EQ(ed.selected(), 0);
}

TEST_F(EditorTest, ObjectPathsEditOneObject) {
  Editor ed("lager", "");
  ed.change(two_glasses(ed.scene()));
  ed.settle(false);
  ed.select(1);
  Scene s = ed.scene();
  set_param(s, parse_param_ref(s, "objects[1].liquid.fill"), 0.25f);
  set_param(s, parse_param_ref(s, "env.floor"), false);
  ed.change(s);
  EXPECT_FLOAT_EQ(ed.document().liquid.fill, 0.25f);  // the selected object
  EXPECT_FALSE(ed.document().env.floor);
  EXPECT_FLOAT_EQ(vessel_document(ed.scene(), 0).liquid.fill, resolve_scene({"lager", "", {}, {}}).liquid.fill);
  ed.select(0);
  EXPECT_FLOAT_EQ(ed.document().liquid.fill, vessel_document(ed.scene(), 0).liquid.fill);
}

TEST_F(EditorTest, ASceneOfSeveralObjectsSavesWholeOrOneGlassAsDrinkOrGlass) {
  Editor ed("lager", "");
  Scene s = two_glasses(ed.scene());
  set_param(s, parse_param_ref(s, "objects[1].liquid.srm"), 30.0f);
  set_param(s, parse_param_ref(s, "env.floor"), false);
  s.objects[1].placement.yaw = 30.0f;
  ed.change(s);
  ed.settle(false);
  ed.select(1);
  // The whole scene: every object with its placement and values loads back the same.
  const fs::path both = dir / "both.json";
  ASSERT_TRUE(ed.save_as(both.string(), "scene")) << ed.status().text;
  const Scene back = resolve_scene_objects({both.string(), "", {}, {}});
  ASSERT_EQ(back.objects.size(), 2u);
  EXPECT_EQ(back.objects[1].name, "second");
  EXPECT_FLOAT_EQ(back.objects[1].placement.position.x, 0.12f);
  EXPECT_FLOAT_EQ(back.objects[1].placement.yaw, 30.0f);
  EXPECT_FLOAT_EQ(vessel_document(back, 1).liquid.srm, 30.0f);
  EXPECT_FLOAT_EQ(vessel_document(back, 0).liquid.srm, vessel_document(ed.scene(), 0).liquid.srm);
  EXPECT_FALSE(back.params.env.floor);
  EXPECT_EQ(dump(vessel_document(back, 1)), dump(vessel_document(ed.scene(), 1)));
  const fs::path drink = dir / "second.json";
  ASSERT_TRUE(ed.save_as(drink.string(), "drink")) << ed.status().text;
  Params p = default_params();
  apply_preset(load_preset(drink), p);
  EXPECT_FLOAT_EQ(p.liquid.srm, 30.0f);  // the selected glass's drink
}

TEST_F(EditorTest, APresetSwitchKeepsTheSelectionInRange) {
  Editor ed("lager", "");
  ed.change(two_glasses(ed.scene()));
  ed.settle(false);
  ed.select(1);
  ASSERT_TRUE(ed.choose_drink("stout"));
  EXPECT_EQ(ed.scene().objects.size(), 1u);
  EXPECT_EQ(ed.selected(), 0);
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(ed.scene().objects.size(), 2u);
  EXPECT_EQ(ed.selected(), 0);
}

TEST_F(EditorTest, AnEnvironmentDroppedInIsOneUndoStepAndABadOneChangesNothing) {
  Editor ed("lager", "");
  const std::string original = dump(ed.document());
  const fs::path broken = dir / "broken.hdr";
  write_file_atomic(broken, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n");  // no pixels
  EXPECT_FALSE(ed.use_environment(broken.string()));
  EXPECT_TRUE(ed.status().error);
  EXPECT_NE(ed.status().text.find("broken.hdr"), std::string::npos) << ed.status().text;
  EXPECT_EQ(dump(ed.document()), original);
  EXPECT_FALSE(ed.use_environment((dir / "missing.exr").string()));
  EXPECT_EQ(dump(ed.document()), original);

  ASSERT_TRUE(ed.use_environment("bar")) << ed.status().text;
  EXPECT_EQ(ed.document().env.mode, int(EnvMode::Image));
  EXPECT_EQ(ed.document().env.image, "bar");
  ASSERT_TRUE(ed.undo());
  EXPECT_EQ(dump(ed.document()), original);
}

}  // namespace
}  // namespace draught::viewer
