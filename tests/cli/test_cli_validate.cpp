// What `validate` accepts renders, and what renders was validated: a drink's suggested
// glass must exist, a preset named "actions" is still a preset, a timeline's preset must
// be a preset; and one broken file in the preset folder does not hide the others from
// `draught presets`.
#include "cli_helpers.hpp"

namespace draught_cli_test {
namespace {

using Validate = CliTest;

const std::string kDrink = R"({"draught_preset": 1, "kind": "drink", "name": "NAME", "suggested_glass": "GLASS",
  "params": {"liquid": {"srm": 8}}})";

TEST_F(Validate, ADrinksSuggestedGlassMustExist) {
  const fs::path f = in() / "drink.json";
  write_file(f, replace(replace(kDrink, "NAME", "amber"), "GLASS", "pnt"));
  auto r = draught({"validate", f.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "field 'suggested_glass'")) << r.describe();
  EXPECT_TRUE(contains(r.err, "pint")) << "did you mean\n" << r.describe();
  write_file(f, replace(replace(kDrink, "NAME", "amber"), "GLASS", "pint"));
  EXPECT_EQ(draught({"validate", f.string()}).exit_code, 0);
}

TEST_F(Validate, APresetNamedActionsIsAPreset) {
  const fs::path f = in() / "actions.json";
  write_file(f, replace(replace(kDrink, "NAME", "actions"), "GLASS", "pint"));
  auto r = draught({"validate", f.string()});
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_TRUE(contains(r.out, "ok (drink 'actions'")) << r.describe();
}

TEST_F(Validate, ATimelinesPresetMustBeAPreset) {
  const fs::path f = in() / "t.json";
  write_file(f, R"({"draught_timeline": 1, "name": "t", "duration": 1, "preset": ")" +
                    (kSourceDir / "presets/timelines/gentle-tilt.json").string() + R"(", "actions": []})");
  auto r = draught({"validate", f.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.err, "field 'preset'")) << r.describe();
}

TEST_F(Validate, OneBrokenPresetDoesNotHideTheOthers) {
  const fs::path dir = in() / "presets";
  fs::create_directories(dir / "drinks");
  fs::create_directories(dir / "glasses");
  fs::copy_file(kSourceDir / "presets/drinks/stout.json", dir / "drinks/stout.json");
  fs::copy_file(kSourceDir / "presets/glasses/pint.json", dir / "glasses/pint.json");
  write_file(dir / "drinks/broken.json", R"({"draught_preset": 1, "kind": "drink", "name": )");
  auto r = draught({"presets"}, {{"DRAUGHT_PRESET_DIR", dir.string()}});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.out, "stout")) << r.describe();
  EXPECT_TRUE(contains(r.out, "pint")) << r.describe();
  EXPECT_TRUE(contains(r.err, "broken.json")) << r.describe();
}

}  // namespace
}  // namespace draught_cli_test
