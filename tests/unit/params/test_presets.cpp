// Preset errors: every bad file gives one complete message (file, field, what was
// expected), nothing is half-applied, and files are written atomically.
#include "core/io/files.hpp"
#include "core/params/preset.hpp"

#include "test_common.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <unistd.h>

namespace draught {
namespace {

// The message of the InputError that parsing `text` as "x.json" throws.
std::string parse_error(const std::string& text) {
  try {
    parse_preset(text, "x.json");
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("wrong exception type: ") + e.what();
  }
  return "no error";
}

::testing::AssertionResult contains(const std::string& message, std::initializer_list<std::string> parts) {
  for (const auto& p : parts)
    if (message.find(p) == std::string::npos)
      return ::testing::AssertionFailure() << "message \"" << message << "\" lacks \"" << p << "\"";
  return ::testing::AssertionSuccess();
}

std::string drink(const std::string& liquid_fields) {
  return R"({ "draught_preset": 1, "kind": "drink", "name": "d", "params": { "liquid": { )" + liquid_fields +
         " } } }";
}

TEST(PresetErrors, MalformedJsonGivesLineAndColumn) {
  // An unquoted value on line 3, column 11.
  const std::string text = "{\n  \"kind\": \"glass\",\n  \"name\": oops,\n  \"params\": {}\n}\n";
  const std::string m = parse_error(text);
  EXPECT_TRUE(contains(m, {"x.json:3:11:", "malformed JSON"}));
  // A missing comma: reported at the unexpected token on line 3 (the parser sees the
  // token once it has read all of it, so the column may point at its end).
  EXPECT_TRUE(contains(parse_error("{\n  \"kind\": \"glass\"\n  \"name\": \"g\"\n}"), {"x.json:3:", "malformed JSON"}));
  // The very first character.
  EXPECT_TRUE(contains(parse_error("x"), {"x.json:1:1:", "malformed JSON"}));
  // Truncated file.
  EXPECT_TRUE(contains(parse_error("{\n  \"kind\": \"glass\",\n"), {"x.json:", "malformed JSON"}));
  EXPECT_TRUE(contains(parse_error(""), {"x.json:", "malformed JSON"}));
}

TEST(PresetErrors, TopLevelMustBeAnObject) {
  for (const char* text : {"[1, 2]", "42", "\"glass\"", "null"})
    EXPECT_TRUE(contains(parse_error(text), {"x.json", "expected a JSON object at the top level"})) << text;
}

TEST(PresetErrors, UnknownTopLevelKey) {
  const std::string m = parse_error(R"({ "kind": "glass", "name": "g", "colour": 1 })");
  EXPECT_TRUE(contains(m, {"x.json", "'colour'", "unknown key", "expected one of", "params"}));
}

TEST(PresetErrors, UnknownParameterSuggestsAName) {
  EXPECT_TRUE(contains(parse_error(drink(R"("srn": 4)")),
                       {"x.json", "params.liquid.srn", "unknown parameter", "did you mean 'liquid.srm'"}));
  // An unknown group.
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "scene", "name": "s", "params": { "liquids": { "srm": 4 } } })"),
                       {"x.json", "params.liquids", "unknown parameter"}));
}

TEST(PresetErrors, GroupThatIsNotAnObject) {
  // "liquid" is a known group: a value that is not an object should be reported as
  // the wrong type for the group, not as an unknown parameter.
  const std::string m = parse_error(R"({ "kind": "drink", "name": "d", "params": { "liquid": 0.5 } })");
  EXPECT_TRUE(contains(m, {"x.json", "params.liquid", "expected", "object"}));
  EXPECT_EQ(m.find("unknown parameter"), std::string::npos) << m;
}

TEST(PresetErrors, WrongType) {
  EXPECT_TRUE(contains(parse_error(drink(R"("srm": "dark")")),
                       {"x.json", "liquid.srm", "expected a number in [0, 100]", "\"dark\""}));
  EXPECT_TRUE(contains(parse_error(drink(R"("haze_color": [1, 0.5])")),
                       {"x.json", "liquid.haze_color", "three numbers", "[1,0.5]"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "scene", "name": "s", "params": { "env": { "floor": 1 } } })"),
                       {"x.json", "env.floor", "true or false", "got 1"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "scene", "name": "s", "params": { "render": { "supersample": 2.5 } } })"),
                       {"x.json", "render.supersample", "a whole number in [1, 4]", "2.5"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "scene", "name": "s", "params": { "render": { "tonemap": 1 } } })"),
                       {"x.json", "render.tonemap", "one of \"none\", \"aces\""}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "glass", "name": "g", "params": { "glass": { "profile": [0.03, 0.1] } } })"),
                       {"x.json", "glass.profile", "2 to 32 points"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": 3, "name": "g" })"), {"x.json", "'kind'", "expected a string"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "glass", "name": "g", "params": [] })"),
                       {"x.json", "'params'", "expected an object"}));
}

TEST(PresetErrors, OutOfRange) {
  EXPECT_TRUE(contains(parse_error(drink(R"("fill": 1.5)")), {"x.json", "liquid.fill", "[0, 0.98]", "1.5"}));
  EXPECT_TRUE(contains(parse_error(drink(R"("ior": 0.5)")), {"x.json", "liquid.ior", "[1, 2]", "0.5"}));
  EXPECT_TRUE(contains(parse_error(drink(R"("absorption": [1, -2, 3])")), {"x.json", "liquid.absorption", "[0, 20000]"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "scene", "name": "s", "params": { "render": { "supersample": 9 } } })"),
                       {"x.json", "render.supersample", "[1, 4]", "9"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "scene", "name": "s", "params": { "render": { "tonemap": "filmic" } } })"),
                       {"x.json", "render.tonemap", "\"filmic\""}));
  EXPECT_TRUE(contains(
      parse_error(R"({ "kind": "glass", "name": "g", "params": { "glass": { "profile": [[0.03, 0.01], [0.04, 0.1]] } } })"),
      {"x.json", "glass.profile", "y starting at 0"}));
  EXPECT_TRUE(contains(
      parse_error(R"({ "kind": "glass", "name": "g", "params": { "glass": { "profile": [[0.03, 0], [0.04, 0.01]] } } })"),
      {"x.json", "glass.profile", "at least 0.02 m tall"}));
  // A float too large for single precision is out of range, not infinity.
  EXPECT_TRUE(contains(parse_error(drink(R"("haze": 1e300)")), {"x.json", "liquid.haze", "[0, 2000]"}));
}

TEST(PresetErrors, IntegersTooLargeForIntAreRejected) {
  // JSON integers outside the range of int must not wrap around into range:
  // 4294967298 = 2^32 + 2 and -4294967294 = -2^32 + 2 are not valid supersample factors.
  for (const char* big : {"4294967298", "-4294967294", "8589934593", "3000000000"}) {
    const std::string text =
        std::string(R"({ "kind": "scene", "name": "s", "params": { "render": { "supersample": )") + big + " } } }";
    const std::string m = parse_error(text);
    EXPECT_TRUE(contains(m, {"x.json", "render.supersample", "[1, 4]"})) << "supersample " << big;
  }
}

TEST(PresetErrors, GlassPresetMayNotSetLiquid) {
  const std::string m = parse_error(
      R"({ "kind": "glass", "name": "g", "params": { "glass": { "ior": 1.5 }, "liquid": { "srm": 4 } } })");
  EXPECT_TRUE(contains(m, {"x.json", "params.liquid.srm", "glass.*", "scene"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "drink", "name": "d", "params": { "glass": { "ior": 1.5 } } })"),
                       {"x.json", "params.glass.ior", "liquid.*"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "glass", "name": "g", "suggested_glass": "pint" })"),
                       {"x.json", "suggested_glass"}));
  // A scene may set anything.
  EXPECT_NO_THROW(parse_preset(
      R"({ "kind": "scene", "name": "s", "params": { "glass": { "ior": 1.5 }, "liquid": { "srm": 4 } } })", "x.json"));
}

TEST(PresetErrors, MissingKindOrName) {
  EXPECT_TRUE(contains(parse_error(R"({ "name": "g" })"), {"x.json", "'kind'", "missing"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "glass" })"), {"x.json", "'name'", "missing"}));
  EXPECT_TRUE(contains(parse_error(R"({ "kind": "mug", "name": "g" })"), {"x.json", "'kind'", "\"glass\"", "\"mug\""}));
  EXPECT_TRUE(contains(parse_error(R"({ "draught_preset": 2, "kind": "glass", "name": "g" })"),
                       {"x.json", "draught_preset", "format 1"}));
  // The smallest valid preset.
  const Preset p = parse_preset(R"({ "kind": "glass", "name": "g" })", "x.json");
  EXPECT_EQ(p.kind, "glass");
  EXPECT_EQ(p.name, "g");
  EXPECT_TRUE(p.values.empty());
}

TEST(PresetErrors, MissingFileNamesThePath) {
  const auto path = std::filesystem::temp_directory_path() / "draught-unit-no-such-dir" / "nothing.json";
  try {
    load_preset(path);
    ADD_FAILURE() << "loaded a missing file";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), {path.string()}));
  }
  // A directory is not a preset either.
  try {
    load_preset(std::filesystem::temp_directory_path());
    ADD_FAILURE() << "loaded a directory";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), {std::filesystem::temp_directory_path().string(), "directory"}));
  }
}

TEST(PresetErrors, LoadPresetUsesThePathInMessages) {
  const auto dir = std::filesystem::temp_directory_path() / ("draught-unit-load-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto file = dir / "bad.json";
  { std::ofstream(file) << drink(R"("fill": 2)"); }
  try {
    load_preset(file);
    ADD_FAILURE() << "loaded a bad preset";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), {file.string(), "liquid.fill"}));
  }
  std::filesystem::remove_all(dir);
}

TEST(PresetErrors, FailedParseNeverHalfApplies) {
  // The first value is fine, the second is not: nothing may change.
  Params p = default_params();
  set_param(p, *find_param("liquid.srm"), 20.0f);
  const Params before = p;
  const std::string text = drink(R"("srm": 4, "ior": 1.4, "fill": 3.0)");
  EXPECT_THROW(apply_preset(parse_preset(text, "x.json"), p), InputError);
  for (const auto& d : param_table()) EXPECT_TRUE(get_param(p, d) == get_param(before, d)) << d.path;
  // The same preset without the bad value applies all of its values.
  apply_preset(parse_preset(drink(R"("srm": 4, "ior": 1.4)"), "x.json"), p);
  EXPECT_EQ(p.liquid.srm, 4.0f);
  EXPECT_EQ(p.liquid.ior, 1.4f);
  EXPECT_EQ(p.liquid.fill, before.liquid.fill);
}

TEST(PresetErrors, KindCheckHappensBeforeAnythingIsApplied) {
  Params p = default_params();
  const Params before = p;
  const std::string text = R"({ "kind": "glass", "name": "g", "params": { "glass": { "ior": 1.9 }, "liquid": { "srm": 30 } } })";
  EXPECT_THROW(apply_preset(parse_preset(text, "x.json"), p), InputError);
  EXPECT_EQ(p.glass.ior, before.glass.ior);
  EXPECT_EQ(p.liquid.srm, before.liquid.srm);
}

// ------------------------------------------------------------------ files --

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir = std::filesystem::temp_directory_path() /
          ("draught-unit-" + std::to_string(::getpid()) + "-" + std::to_string(rd()));
    std::filesystem::create_directories(dir);
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
  std::filesystem::path dir;
};

TEST_F(TempDir, WriteFileAtomicLeavesNoTemporaryFile) {
  const auto file = dir / "out.json";
  write_file_atomic(file, "first");
  EXPECT_EQ(read_text_file(file), "first");
  EXPECT_EQ(names(), std::vector<std::string>{"out.json"});
  write_file_atomic(file, std::string("second\0with nul", 15));
  EXPECT_EQ(read_text_file(file), std::string("second\0with nul", 15));
  write_file_atomic(file, "");
  EXPECT_EQ(read_text_file(file), "");
  EXPECT_EQ(names(), std::vector<std::string>{"out.json"});
}

TEST_F(TempDir, WriteFileAtomicReplacesTheFileRatherThanRewritingIt) {
  // A hard link to the old file keeps the old content: the new content arrived by
  // rename, so a reader never sees a truncated or half-written file.
  const auto file = dir / "image.png", old_link = dir / "old-link";
  write_file_atomic(file, "old content");
  std::filesystem::create_hard_link(file, old_link);
  write_file_atomic(file, "new content, longer than the old");
  EXPECT_EQ(read_text_file(file), "new content, longer than the old");
  EXPECT_EQ(read_text_file(old_link), "old content");
  EXPECT_EQ(names(), (std::vector<std::string>{"image.png", "old-link"}));
}

TEST_F(TempDir, WriteFileAtomicFailureNamesTheFileAndCleansUp) {
  const auto missing = dir / "no-such-subdir" / "out.json";
  try {
    write_file_atomic(missing, "x");
    ADD_FAILURE() << "wrote into a missing directory";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), {missing.string(), "cannot write"}));
  }
  // The target is a directory: the rename fails; the temporary must be removed.
  std::filesystem::create_directory(dir / "target");
  std::filesystem::create_directory(dir / "target" / "inside");  // non-empty, so rename cannot replace it
  EXPECT_THROW(write_file_atomic(dir / "target", "x"), InputError);
  EXPECT_EQ(names(), std::vector<std::string>{"target"});
}

TEST_F(TempDir, SavePresetValidatesBeforeWriting) {
  const auto file = dir / "mine.json";
  EXPECT_THROW(save_preset(file, R"({ "kind": "glass" })"), InputError);
  EXPECT_FALSE(std::filesystem::exists(file));
  const std::string good = preset_json(default_params(), "glass", "mine", "", {"glass"});
  save_preset(file, good);
  EXPECT_EQ(read_text_file(file), good);
  EXPECT_THROW(save_preset(file, "{ broken"), InputError);
  EXPECT_EQ(read_text_file(file), good) << "a rejected save must leave the old file alone";
  EXPECT_EQ(names(), std::vector<std::string>{"mine.json"});
  // And it loads back.
  const Preset p = load_preset(file);
  EXPECT_EQ(p.name, "mine");
}

}  // namespace
}  // namespace draught
