// End-to-end tests of bad timeline files: `draught render --timeline FILE` and
// `draught validate FILE` must both exit 1, name the file, the field and what was
// expected, and write nothing.
#include "cli_helpers.hpp"


namespace draught_cli_test {
namespace {

// A valid timeline, one action per line so that tests can break a known line.
const char* kGoodTimeline =
    "{\n"                                                                                     // 1
    "  \"draught_timeline\": 1,\n"                                                            // 2
    "  \"name\": \"test\",\n"                                                                 // 3
    "  \"duration\": 1,\n"                                                                    // 4
    "  \"actions\": [\n"                                                                      // 5
    "    { \"at\": 0, \"action\": \"set\", \"param\": \"liquid.srm\", \"value\": 20 },\n"     // 6
    "    { \"at\": 0.1, \"action\": \"tilt\", \"angle\": 20, \"duration\": 0.5 },\n"          // 7
    "    { \"at\": 0.2, \"action\": \"shake\", \"amplitude\": 0.005, \"frequency\": 2, \"duration\": 0.5 },\n"  // 8
    "    { \"at\": 0.3, \"action\": \"sip\", \"amount\": 0.1, \"duration\": 0.5 }\n"          // 9
    "  ]\n"                                                                                   // 10
    "}\n";

class TimelineErrors : public CliTest {
 protected:
  fs::path timeline_file(const std::string& name, const std::string& text) {
    write_file(in() / name, text);
    return in() / name;
  }
  // `render --timeline FILE -o out/frames/` (small and short, were it to run).
  RunResult render_timeline(const std::string& timeline) {
    return draught({"render", "--timeline", timeline, "--size", "16x16", "--supersample", "1", "--fps", "2",
                    "--duration", "0.5", "-o", (out() / "frames").string() + "/"});
  }
  RunResult validate(const std::string& file) { return draught({"validate", file}); }

  // Both commands fail on `text` (written to in()/name) with exit code 1 and every needle
  // in stderr; render writes nothing. {file} in a needle stands for the file's path.
  void expect_both_fail(const std::string& name, const std::string& text, std::vector<std::string> needles) {
    const fs::path f = timeline_file(name, text);
    needles.insert(needles.begin(), f.string());
    {
      SCOPED_TRACE("draught render --timeline " + f.string());
      auto r = render_timeline(f.string());
      EXPECT_EQ(r.exit_code, 1) << r.describe();
      expect_failure(r, needles);
    }
    {
      SCOPED_TRACE("draught validate " + f.string());
      auto r = validate(f.string());
      EXPECT_EQ(r.exit_code, 1) << r.describe();
      EXPECT_FALSE(contains(r.out, ": ok")) << r.describe();
      for (auto& n : needles) EXPECT_TRUE(contains(r.err, n)) << "stderr lacks \"" << n << "\"\n" << r.describe();
    }
  }
};

// ---------------------------------------------------------------- the template and the shipped files

TEST_F(TimelineErrors, GoodTemplateIsGood) {  // the base the other cases break
  const fs::path f = timeline_file("good.json", kGoodTimeline);
  auto v = validate(f.string());
  EXPECT_EQ(v.exit_code, 0) << v.describe();
  EXPECT_TRUE(contains(v.out, f.string() + ": ok")) << v.describe();
  EXPECT_TRUE(contains(v.out, "4 actions")) << v.describe();
  auto r = render_timeline(f.string());
  ASSERT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(join(list_tree(out() / "frames")), "frame_00000.png");
}

TEST_F(TimelineErrors, ShippedTimelinesValidate) {
  std::vector<std::string> files;
  for (auto& e : fs::directory_iterator(kSourceDir / "presets" / "timelines"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 3u) << "expected the 3 shipped timelines";
  std::vector<std::string> args = {"validate"};
  args.insert(args.end(), files.begin(), files.end());
  auto r = draught(args);
  EXPECT_EQ(r.exit_code, 0) << r.describe();
  EXPECT_EQ(r.err, "") << r.describe();
  for (auto& f : files) {
    EXPECT_TRUE(contains(r.out, f + ": ok (timeline '" + fs::path(f).stem().string() + "'"))
        << f << " not reported ok, or its name differs from its file name\n" << r.describe();
  }
}

TEST_F(TimelineErrors, ValidateReportsEveryBadFileAndStillChecksTheGoodOnes) {
  const fs::path good = timeline_file("good.json", kGoodTimeline);
  const fs::path bad = timeline_file("bad.json", replace(kGoodTimeline, "\"angle\": 20", "\"angle\": 200"));
  auto r = draught({"validate", bad.string(), good.string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  EXPECT_TRUE(contains(r.out, good.string() + ": ok")) << r.describe();
  EXPECT_TRUE(contains(r.err, bad.string())) << r.describe();
  EXPECT_FALSE(contains(r.out, bad.string() + ": ok")) << r.describe();
}

// ---------------------------------------------------------------- the file as a whole

TEST_F(TimelineErrors, MalformedJsonGivesFileLineColumn) {
  // A missing comma at the end of line 7: the parser stops at the "{" on line 8.
  const std::string text = replace(kGoodTimeline, "\"duration\": 0.5 },\n    { \"at\": 0.2",
                                   "\"duration\": 0.5 }\n    { \"at\": 0.2");
  expect_both_fail("broken.json", text, {":8:", "malformed JSON"});
  const fs::path f = in() / "broken.json";
  auto r = validate(f.string());
  EXPECT_TRUE(matches(r.err, literal_pattern(f.string()) + ":8:[0-9]+: malformed JSON"))
      << "no file:line:col\n" << r.describe();
}

TEST_F(TimelineErrors, TruncatedJson) {
  expect_both_fail("truncated.json", std::string(kGoodTimeline).substr(0, 120), {"malformed JSON"});
}

TEST_F(TimelineErrors, MissingFormatKey) {
  // Without "draught_timeline" the file is not recognisably a timeline; render (which
  // knows it wants one) must say the key is missing.
  const fs::path f = timeline_file("noformat.json", replace(kGoodTimeline, "  \"draught_timeline\": 1,\n", ""));
  auto r = render_timeline(f.string());
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {f.string(), "draught_timeline", "expected format 1", "missing"});
  auto v = validate(f.string());
  EXPECT_EQ(v.exit_code, 1) << v.describe();
  EXPECT_TRUE(contains(v.err, f.string())) << v.describe();
  EXPECT_FALSE(contains(v.out, ": ok")) << v.describe();
}

TEST_F(TimelineErrors, WrongFormatNumber) {
  expect_both_fail("format.json", replace(kGoodTimeline, "\"draught_timeline\": 1", "\"draught_timeline\": 2"),
                   {"draught_timeline", "expected format 1", "got 2"});
}

TEST_F(TimelineErrors, UnknownTopLevelKey) {
  expect_both_fail("key.json", replace(kGoodTimeline, "\"name\"", "\"speed\": 2,\n  \"name\""),
                   {"'speed'", "unknown key", "expected one of", "actions", "duration"});
}

TEST_F(TimelineErrors, ActionsNotAnArray) {
  const std::string text = "{ \"draught_timeline\": 1, \"name\": \"x\", \"actions\": { \"at\": 0 } }\n";
  expect_both_fail("actions.json", text, {"'actions'", "expected an array"});
}

TEST_F(TimelineErrors, MissingActions) {
  expect_both_fail("noactions.json", "{ \"draught_timeline\": 1, \"name\": \"x\" }\n",
                   {"'actions'", "expected an array"});
}

TEST_F(TimelineErrors, TopLevelNotAnObject) {
  expect_both_fail("array.json", "[ \"draught_timeline\", 1 ]\n", {"object"});
}

TEST_F(TimelineErrors, WrongTypeForName) {
  expect_both_fail("name.json", replace(kGoodTimeline, "\"name\": \"test\"", "\"name\": 7"),
                   {"'name'", "expected a string", "7"});
}

TEST_F(TimelineErrors, TopLevelDurationOutOfRange) {
  expect_both_fail("dur.json", replace(kGoodTimeline, "\"duration\": 1,", "\"duration\": 0,"),
                   {"'duration'", "[0.01, 600]", "got 0"});
}

// ---------------------------------------------------------------- actions

TEST_F(TimelineErrors, UnknownActionKindListsTheValidOnes) {
  expect_both_fail("kind.json", replace(kGoodTimeline, "\"action\": \"tilt\"", "\"action\": \"tip\""),
                   {"actions[1].action", "\"tip\"", "tilt, rotate, shake, sip, orbit, set"});
}

TEST_F(TimelineErrors, MissingActionKind) {
  expect_both_fail("nokind.json", replace(kGoodTimeline, "\"action\": \"tilt\", ", ""),
                   {"actions[1].action", "missing", "tilt, rotate, shake, sip, orbit, set"});
}

TEST_F(TimelineErrors, ActionNotAnObject) {
  expect_both_fail("notobj.json", replace(kGoodTimeline, "{ \"at\": 0.3, \"action\": \"sip\", \"amount\": 0.1, "
                                                         "\"duration\": 0.5 }",
                                          "\"sip\""),
                   {"actions[3]", "expected an action object", "\"sip\""});
}

TEST_F(TimelineErrors, TiltMissingAngle) {
  expect_both_fail("angle.json", replace(kGoodTimeline, "\"angle\": 20, ", ""),
                   {"actions[1].angle", "missing", "[0, 135]"});
}

TEST_F(TimelineErrors, ShakeMissingAmplitude) {
  expect_both_fail("amp.json", replace(kGoodTimeline, "\"amplitude\": 0.005, ", ""),
                   {"actions[2].amplitude", "missing", "[0, 0.1]"});
}

TEST_F(TimelineErrors, ShakeMissingFrequency) {
  expect_both_fail("freq.json", replace(kGoodTimeline, "\"frequency\": 2, ", ""),
                   {"actions[2].frequency", "missing", "[0.1, 20]"});
}

TEST_F(TimelineErrors, ShakeMissingDuration) {
  expect_both_fail("shakedur.json", replace(kGoodTimeline, "\"frequency\": 2, \"duration\": 0.5", "\"frequency\": 2"),
                   {"actions[2].duration", "missing", "[0.05, 3600]"});
}

TEST_F(TimelineErrors, SipMissingAmount) {
  expect_both_fail("sipamount.json", replace(kGoodTimeline, "\"amount\": 0.1, ", ""),
                   {"actions[3].amount", "missing", "[0, 1]"});
}

TEST_F(TimelineErrors, AngleOutOfRange) {
  expect_both_fail("angle200.json", replace(kGoodTimeline, "\"angle\": 20", "\"angle\": 200"),
                   {"actions[1].angle", "[0, 135]", "degrees", "got 200"});
}

TEST_F(TimelineErrors, NegativeAngle) {
  expect_both_fail("angleneg.json", replace(kGoodTimeline, "\"angle\": 20", "\"angle\": -1"),
                   {"actions[1].angle", "[0, 135]", "got -1"});
}

TEST_F(TimelineErrors, AngleOfWrongType) {
  expect_both_fail("anglestr.json", replace(kGoodTimeline, "\"angle\": 20", "\"angle\": \"20\""),
                   {"actions[1].angle", "expected a number", "\"20\""});
}

TEST_F(TimelineErrors, FrequencyZero) {
  expect_both_fail("freq0.json", replace(kGoodTimeline, "\"frequency\": 2", "\"frequency\": 0"),
                   {"actions[2].frequency", "[0.1, 20]", "Hz", "got 0"});
}

TEST_F(TimelineErrors, SipAmountTwo) {
  expect_both_fail("amount2.json", replace(kGoodTimeline, "\"amount\": 0.1", "\"amount\": 2"),
                   {"actions[3].amount", "[0, 1]", "got 2"});
}

TEST_F(TimelineErrors, NegativeDuration) {
  expect_both_fail("dur-1.json",
                   replace(kGoodTimeline, "\"angle\": 20, \"duration\": 0.5", "\"angle\": 20, \"duration\": -1"),
                   {"actions[1].duration", "[0, 3600]", "seconds", "got -1"});
}

TEST_F(TimelineErrors, NegativeAt) {
  expect_both_fail("at-5.json", replace(kGoodTimeline, "\"at\": 0.3", "\"at\": -5"),
                   {"actions[3].at", "[0, 3600]", "got -5"});
}

TEST_F(TimelineErrors, UnknownParameterInSetSuggestsTheRightOne) {
  expect_both_fail("param.json", replace(kGoodTimeline, "\"liquid.srm\"", "\"liquid.sr\""),
                   {"actions[0].param", "unknown parameter 'liquid.sr'", "did you mean 'liquid.srm'"});
}

TEST_F(TimelineErrors, SetValueOfWrongType) {
  expect_both_fail("value.json", replace(kGoodTimeline, "\"value\": 20", "\"value\": \"dark\""),
                   {"actions[0].value", "expected a number in [0, 100]", "\"dark\""});
}

TEST_F(TimelineErrors, SetValueOutOfRange) {
  expect_both_fail("value-range.json", replace(kGoodTimeline, "\"value\": 20", "\"value\": 500"),
                   {"actions[0].value", "[0, 100]", "500"});
}

TEST_F(TimelineErrors, SetMissingValue) {
  expect_both_fail("novalue.json", replace(kGoodTimeline, ", \"value\": 20", ""),
                   {"actions[0].value", "missing", "[0, 100]"});
}

TEST_F(TimelineErrors, SetMissingParam) {
  expect_both_fail("noparam.json", replace(kGoodTimeline, "\"param\": \"liquid.srm\", ", ""),
                   {"actions[0].param", "missing", "liquid.srm"});
}

TEST_F(TimelineErrors, UnknownKeyInsideAction) {
  expect_both_fail("actionkey.json", replace(kGoodTimeline, "\"angle\": 20,", "\"angle\": 20, \"speed\": 3,"),
                   {"actions[1].speed", "unknown key", "angle", "toward"});
}

TEST_F(TimelineErrors, KeyOfAnotherActionKind) {
  // "amount" belongs to sip, not tilt.
  expect_both_fail("otherkey.json", replace(kGoodTimeline, "\"angle\": 20,", "\"angle\": 20, \"amount\": 0.1,"),
                   {"actions[1].amount", "unknown key"});
}

TEST_F(TimelineErrors, BadEase) {
  expect_both_fail("ease.json", replace(kGoodTimeline, "\"angle\": 20,", "\"angle\": 20, \"ease\": \"fast\","),
                   {"actions[1].ease", "\"smooth\"", "\"linear\"", "\"fast\""});
}

TEST_F(TimelineErrors, ErrorsNameTheOriginalIndexNotTheSortedOne) {
  // Actions are sorted by time after parsing; a bad action listed last but starting first
  // is still actions[4].
  expect_both_fail("order.json",
                   replace(kGoodTimeline, " }\n  ]", " },\n    { \"at\": 0, \"action\": \"tilt\", \"angle\": 999 }\n  ]"),
                   {"actions[4].angle", "[0, 135]"});
}

TEST_F(TimelineErrors, SeveralMistakesAreAllReportedOnePerLine) {
  // Three mistakes in two actions: every one is reported, each on its own line naming the
  // file and the field, under a line that counts them.
  std::string text = replace(kGoodTimeline, "\"angle\": 20", "\"angle\": 200");
  text = replace(text, "\"amount\": 0.1", "\"amount\": 2");
  text = replace(text, "\"frequency\": 2", "\"frequency\": 0");
  expect_both_fail("several.json", text,
                   {"3 mistakes:", "actions[1].angle", "got 200", "actions[2].frequency", "actions[3].amount", "got 2"});
  const fs::path f = in() / "several.json";
  auto r = validate(f.string());
  for (const char* field : {"actions[1].angle", "actions[2].frequency", "actions[3].amount"})
    EXPECT_TRUE(contains(r.err, "\n  " + f.string() + ": field '" + field + "': ")) << field << "\n" << r.describe();
}

// ---------------------------------------------------------------- names and paths

TEST_F(TimelineErrors, NonexistentTimelineNameSaysWhereItLooked) {
  auto r = render_timeline("no-such-timeline");
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"no-such-timeline", "looked for",
                     (kSourceDir / "presets" / "timelines" / "no-such-timeline.json").string()});
}

TEST_F(TimelineErrors, NonexistentTimelineFile) {
  const std::string f = (in() / "missing.json").string();
  auto r = render_timeline(f);
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {f});
  auto v = validate(f);
  EXPECT_EQ(v.exit_code, 1) << v.describe();
  EXPECT_TRUE(contains(v.err, f)) << v.describe();
}

TEST_F(TimelineErrors, PresetGivenAsTimeline) {
  // A drink preset is not a timeline: render says what it expected.
  const std::string f = (kSourceDir / "presets" / "drinks" / "lager.json").string();
  auto r = render_timeline(f);
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {f, "draught_timeline"});
}

TEST_F(TimelineErrors, TimelineGivenAsPreset) {
  const std::string f = (kSourceDir / "presets" / "timelines" / "gentle-tilt.json").string();
  auto r = draught({"render", "--preset", f, "--size", "16x16", "-o", (out() / "x.png").string()});
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {f});
}

TEST_F(TimelineErrors, TimelineNamingAMissingPreset) {
  const fs::path f = timeline_file(
      "scene.json", replace(kGoodTimeline, "\"name\": \"test\",", "\"name\": \"test\", \"preset\": \"no-such-drink\","));
  auto r = render_timeline(f.string());
  EXPECT_EQ(r.exit_code, 1) << r.describe();
  expect_failure(r, {"no-such-drink", "draught presets"});
}

}  // namespace
}  // namespace draught_cli_test
