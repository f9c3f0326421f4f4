// End-to-end tests of hostile input and command-line mistakes (issue "Hardening"):
// deep and huge JSON, files that are not files, bad flag values, typos. Every case
// exits 1 with "draught: error: " naming what was wrong and what was expected, never
// crashes, and writes nothing.
#include "../support/utf8.hpp"
#include "cli_helpers.hpp"

#include <sys/stat.h>

namespace draught_cli_test {
namespace {

class Hostile : public CliTest {
 protected:
  fs::path png() const { return out() / "x.png"; }
  fs::path input(const std::string& name, const std::string& text) {
    write_file(in() / name, text);
    return in() / name;
  }
  // A failure with exit code 1 (not a CLI11 code, not a crash), "draught: error: " first.
  void expect_error(const RunResult& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 1) << r.describe();
    EXPECT_TRUE(r.err.starts_with("draught: error: ")) << r.describe();
    expect_failure(r, needles);
  }
  // `validate` reports each bad file on a line of its own, starting with the file.
  void expect_invalid(const RunResult& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 1) << r.describe();
    expect_failure(r, needles);
  }
};

std::string nested(size_t depth) { return std::string(depth, '[') + "1" + std::string(depth, ']'); }

std::string drink_with(const std::string& field_and_value) {
  return R"({ "draught_preset": 1, "kind": "drink", "name": "x", )" + field_and_value + " }";
}

using draught::test::valid_utf8;

// ---------------------------------------------------------------- 1. deep nesting

TEST_F(Hostile, DeeplyNestedDescriptionIsRefusedNotACrash) {
  // 100,000 nested arrays crashed the CLI (stack overflow while echoing the value).
  const fs::path f = input("deep.json", drink_with("\"description\": " + nested(100000)));
  for (auto args :
       {std::vector<std::string>{"validate", f.string()},
        std::vector<std::string>{"render", "--size", "16x16", "--preset", f.string(), "-o", png().string()}}) {
    auto r = draught(args);
    expect_invalid(r, {f.string() + ": field 'description': nested more than 256 levels deep"});
    EXPECT_LT(r.err.size(), 400u) << "the message repeats the value";
  }
}

TEST_F(Hostile, DeeplyNestedParameterAndTimelineValues) {
  const fs::path p = input("fill.json", drink_with(R"("params": { "liquid": { "fill": )" + nested(60000) + " } }"));
  expect_invalid(draught({"validate", p.string()}),
                 {p.string() + ": field 'params.liquid.fill': nested more than 256"});
  const fs::path t = input("t.json", R"({ "draught_timeline": 1, "actions": [
      { "at": 0, "action": "set", "param": "liquid.srm", "value": )" +
                                         nested(60000) + " } ] }");
  expect_error(draught({"render", "--timeline", t.string(), "--size", "16x16", "-o", (out() / "f").string() + "/"}),
               {t.string() + ": field 'actions[0].value': nested more than 256"});
}

// ---------------------------------------------------------------- 3. capped, whole UTF-8 echoes

TEST_F(Hostile, EchoedValuesAreCappedAndValidUtf8) {
  std::string euros;
  for (int i = 0; i < 50000; ++i) euros += "\xE2\x82\xAC";
  // A string where a number belongs, an array where a string belongs, a bad kind.
  for (const std::string& bad : {R"("params": { "liquid": { "fill": ")" + euros + "\" } }",
                                 "\"description\": [\"" + euros + "\"]", "\"kind\": \"" + euros + "\""}) {
    const fs::path f = input("utf8.json", drink_with(bad));
    auto r = draught({"validate", f.string()});
    EXPECT_EQ(r.exit_code, 1) << r.describe().substr(0, 500);
    EXPECT_TRUE(contains(r.err, f.string() + ": field '")) << r.describe().substr(0, 500);
    EXPECT_TRUE(contains(r.err, "\xE2\x82\xAC...")) << "no capped echo: " << r.err.substr(0, 300);
    EXPECT_LT(r.err.size(), 300u) << "echoed the whole value";
    EXPECT_TRUE(valid_utf8(r.err)) << "a UTF-8 character was cut: " << r.err;
  }
}

TEST_F(Hostile, ALongSetValueIsEchoedCapped) {
  // --set took the whole text into its message: a pasted page came back in full.
  std::string euros;
  for (int i = 0; i < 20000; ++i) euros += "\xE2\x82\xAC";
  auto r = draught({"render", "--size", "16x16", "--set", "liquid.fill=" + euros, "-o", png().string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe().substr(0, 500);
  EXPECT_TRUE(contains(r.err, "field 'liquid.fill'")) << r.err.substr(0, 300);
  EXPECT_LT(r.err.size(), 600u) << "echoed the whole value";
  EXPECT_TRUE(valid_utf8(r.err)) << "a UTF-8 character was cut";
}

// ---------------------------------------------------------------- 5. files that are not files

TEST_F(Hostile, DevZeroAsPresetIsRefusedAtOnce) {
  auto r = draught({"render", "--size", "16x16", "--preset", "/dev/zero", "-o", png().string()});
  expect_error(r, {"/dev/zero: is a character device, expected a regular file"});
}

TEST_F(Hostile, FifoAsPresetOrTimelineDoesNotHang) {
  const fs::path fifo = in() / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  auto v = run_draught({"validate", fifo.string()}, dir_ / "cap", {}, std::chrono::seconds(20));
  EXPECT_FALSE(v.timed_out) << "validate waited on the FIFO";
  expect_invalid(v, {fifo.string() + ": is a FIFO (named pipe), expected a regular file"});
  auto t = run_draught({"render", "--timeline", fifo.string(), "-o", (out() / "f").string() + "/"}, dir_ / "cap", {},
                       std::chrono::seconds(20));
  expect_error(t, {fifo.string() + ": is a FIFO"});
}

TEST_F(Hostile, OversizedPresetIsRefusedNamingTheLimit) {
  const fs::path big = input("big.json", "{}");
  fs::resize_file(big, (16u << 20) + 4096);  // sparse
  expect_invalid(draught({"validate", big.string()}), {big.string() + ": 16.0 MiB, larger than the limit of 16 MiB"});
}

TEST_F(Hostile, DirectoryAsTimeline) {
  fs::create_directories(in() / "dir.json");
  expect_invalid(draught({"validate", (in() / "dir.json").string()}), {"dir.json: is a directory"});
}

// ---------------------------------------------------------------- 10. the command line

TEST_F(Hostile, UnknownVerbSuggestsTheNearest) {
  auto r = draught({"rendr", "--preset", "lager"});
  expect_error(r, {"draught: error: unknown command \"rendr\" (did you mean 'render'?)", "presets, validate"});
  EXPECT_FALSE(contains(r.err, "subcommand is required")) << r.describe();
  expect_error(draught({"coffee"}),
               {"unknown command \"coffee\"; expected render, presets, validate, params, environment or bench"});
}

TEST_F(Hostile, UnknownFlagSuggestsTheNearest) {
  expect_error(render({"--fsp", "30", "-o", png().string()}),
               {"draught: error: unknown flag \"--fsp\" for `draught render` (did you mean '--fps'?)",
                "`draught render --help`"});
  expect_error(draught({"presets", "--markdwn"}), {"unknown flag \"--markdwn\" for `draught presets`"});
  expect_error(draught({"params", "--markdwn"}), {"(did you mean '--markdown'?)"});
  expect_error(render({"-o", png().string(), "stray"}), {"unexpected argument \"stray\" for `draught render`"});
}

TEST_F(Hostile, MissingValueAndMissingFiles) {
  expect_error(render({"--fps"}), {"draught: error: --fps: expected a value after it", "Frames per second"});
  expect_error(draught({"validate"}), {"validate: expected one or more preset or timeline files"});
  expect_error(draught({}), {"expected a command: render, presets, validate, params, environment or bench"});
}

TEST_F(Hostile, BadNumbersNameFlagValueAndRange) {
  const std::string frames = (out() / "f").string() + "/";
  for (const char* v : {"nan", "inf", "abc", "30fps", "0", "121", ""})
    expect_error(draught({"render", "--timeline", "gentle-tilt", "--size", "16x16", "--fps", v, "-o", frames}),
                 {"draught: error: --fps " + std::string(v) + ": expected a number from 1 to 120 (frames per second)"});
  for (const char* v : {"nan", "0", "1e9"})
    expect_error(draught({"render", "--timeline", "gentle-tilt", "--size", "16x16", "--duration", v, "-o", frames}),
                 {"--duration " + std::string(v) + ": expected a number from 0.01 to 600 (seconds)"});
  expect_error(render({"--supersample", "2.5", "-o", png().string()}),
               {"--supersample 2.5: expected a whole number from 1 to 4"});
  expect_error(draught({"bench", "--frames", "0"}), {"--frames 0: expected a whole number from 1 to 10000"});
  expect_error(draught({"bench", "--sizes", "64,big"}), {"--sizes 64,big: expected whole numbers", "got \"big\""});
}

TEST_F(Hostile, BadChoicesSuggest) {
  expect_error(render({"--debug", "normals", "-o", png().string()}),
               {"--debug normals: expected depth, normal, material or cost (did you mean 'normal'?)"});
  expect_error(render({"--tonemap", "acse", "-o", png().string()}),
               {"--tonemap acse: expected none or aces (did you mean 'aces'?)"});
}

TEST_F(Hostile, PresetGlassAndTimelineNamesSuggest) {
  expect_error(render({"--preset", "lagr", "-o", png().string()}),
               {"--preset lagr: no drink preset named \"lagr\" (did you mean 'lager'?)", "draught presets"});
  expect_error(render({"--glass", "pnt", "-o", png().string()}),
               {"--glass pnt: no glass preset named \"pnt\" (did you mean 'pint'?)"});
  expect_error(draught({"render", "--timeline", "gentle-tlt", "-o", (out() / "f").string() + "/"}),
               {"--timeline gentle-tlt: no timeline named \"gentle-tlt\" (did you mean 'gentle-tilt'?)"});
}

TEST_F(Hostile, CameraWithEyeOnTargetIsRefused) {
  expect_error(render({"--camera", "eye=0,0.1,0.3", "target=0,0.1,0.3", "-o", png().string()}),
               {"--camera: camera.eye and camera.target are the same point (0, 0.1, 0.3)", "direction"});
  expect_error(render({"--set", "camera.eye=0,0.07,0", "--set", "camera.target=0,0.07,0", "-o", png().string()}),
               {"camera.eye and camera.target are the same point"});
}

TEST_F(Hostile, BogusDeviceIsRefusedWithTheValidValues) {
  auto r = draught({"render", "--size", "16x16", "-o", png().string()}, {{"DRAUGHT_DEVICE", "bogus"}});
  expect_error(r, {"DRAUGHT_DEVICE=bogus: expected software, hardware or auto"});
  auto s = draught({"render", "--size", "16x16", "-o", png().string()}, {{"DRAUGHT_DEVICE", "sofware"}});
  expect_error(s, {"(did you mean 'software'?)"});
}

TEST_F(Hostile, FramebufferTooLargeNamesTheSizeAndTheLimit) {
  auto r = render({"--size", "5000x5000", "--supersample", "4", "-o", png().string()});
  expect_error(r, {"--size 5000x5000 at --supersample 4 (rendered at 20000x20000",
                   "cannot create an offscreen framebuffer of 20000x20000 pixels: larger than this GL driver's limit",
                   "GL_MAX_TEXTURE_SIZE"});
}

TEST_F(Hostile, LimitsAreNamedInTheMessagesThatEnforceThem) {
  std::string points;
  for (int i = 0; i < 33; ++i) points += std::string(i ? "," : "") + "[0.03, " + std::to_string(i * 0.005) + "]";
  const fs::path g = input("g.json", R"({ "draught_preset": 1, "kind": "glass", "name": "g",
      "params": { "glass": { "profile": [)" +
                                         points + "] } } }");
  expect_invalid(draught({"validate", g.string()}), {g.string(), "glass.profile", "2 to 32 points"});
  const fs::path s = input("s.json", R"({ "draught_preset": 1, "kind": "glass", "name": "g",
      "params": { "glass": { "profile": [[0.03, 0], [0.03, 0.01]] } } })");
  expect_invalid(draught({"validate", s.string()}), {s.string(), "glass.profile", "at least 0.02 m tall"});
}

}  // namespace
}  // namespace draught_cli_test
