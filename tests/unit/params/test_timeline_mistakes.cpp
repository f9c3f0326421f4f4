// A timeline with several mistakes reports all of them, one per line, each with the file
// and its field (actions[N]. names the action as written); a single mistake keeps its
// one-line message; a long list is capped.
#include "core/io/files.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace draught {
namespace {

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t end; (end = s.find('\n', start)) != std::string::npos; start = end + 1) out.push_back(s.substr(start, end - start));
  out.push_back(s.substr(start));
  return out;
}

std::string timeline_error_of(const std::string& text, const std::string& file = "t.json") {
  try {
    parse_timeline(text, file);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << text;
  return "";
}

const std::string kHead = R"({"draught_timeline": 1, "name": "t", "actions": [)";

TEST(TimelineMistakes, OneMistakeIsOneLineAsBefore) {
  const std::string e = timeline_error_of(kHead + R"({"at": 0, "action": "tilt", "angle": 200}]})");
  EXPECT_EQ(e, "t.json: field 'actions[0].angle': expected a number in [0, 135] (degrees), got 200");
}

TEST(TimelineMistakes, EveryMistakeIsListedWithItsField) {
  // Mistakes in three actions (one of them twice), an unknown action kind and a bad
  // top-level field: all of them, in file order, each naming the file and the field.
  const std::string e = timeline_error_of(R"({"draught_timeline": 1, "name": "t", "fps": 500, "actions": [
      {"at": 0, "action": "tilt", "angle": 200},
      {"at": 1, "action": "sip", "amount": 0.1},
      {"at": 2, "action": "shake", "amplitude": 5, "frequency": 0, "duration": 1},
      {"at": -1, "action": "tip"},
      {"at": 0, "action": "set", "param": "liquid.sr", "value": 3}]})");
  const std::vector<std::string> lines = lines_of(e);
  ASSERT_EQ(lines.size(), 8u) << e;
  EXPECT_EQ(lines[0], "t.json: 7 mistakes:");
  const char* fields[] = {"actions[0].angle", "actions[2].amplitude", "actions[2].frequency", "actions[3].at",
                          "actions[3].action", "actions[4].param", "fps"};
  for (size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(lines[i + 1].rfind("  t.json: field '" + std::string(fields[i]) + "': ", 0), 0u)
        << "line " << i + 1 << ": " << lines[i + 1];
  }
  EXPECT_NE(lines[3].find("[0.1, 20]"), std::string::npos) << lines[3];
  EXPECT_NE(e.find("did you mean 'liquid.srm'"), std::string::npos) << e;
}

TEST(TimelineMistakes, UnknownKindIsReportedBesideOtherMistakes) {
  const std::string e = timeline_error_of(kHead + R"({"at": 0, "action": "tip"}, {"at": 0, "action": "sip", "amount": 7}]})");
  const std::vector<std::string> lines = lines_of(e);
  ASSERT_EQ(lines.size(), 3u) << e;
  EXPECT_NE(lines[1].find("field 'actions[0].action': expected one of tilt"), std::string::npos) << e;
  EXPECT_NE(lines[2].find("field 'actions[1].amount'"), std::string::npos) << e;
}

TEST(TimelineMistakes, ALongListIsCapped) {
  std::string text = kHead;
  for (int i = 0; i < 50; ++i) text += std::string(i ? "," : "") + R"({"at": 0, "action": "tilt", "angle": 999})";
  const std::string e = timeline_error_of(text + "]}");
  const std::vector<std::string> lines = lines_of(e);
  ASSERT_EQ(lines.size(), 22u) << e;
  EXPECT_EQ(lines.front(), "t.json: 50 mistakes:");
  EXPECT_NE(lines[20].find("actions[19].angle"), std::string::npos) << lines[20];
  EXPECT_EQ(lines.back(), "  ... and 30 more");
}

TEST(TimelineMistakes, NotATimelineIsOneMistake) {
  // A wrong format says nothing about the rest of the file: only that is reported.
  const std::string e = timeline_error_of(R"({"draught_timeline": 2, "speed": 1, "actions": 3})");
  EXPECT_EQ(lines_of(e).size(), 1u) << e;
  EXPECT_NE(e.find("field 'draught_timeline': expected format 1, got 2"), std::string::npos) << e;
}

TEST(TimelineMistakes, BindingReportsEveryUnknownObject) {
  Timeline t = parse_timeline(kHead + R"(
      {"at": 1, "action": "sip", "amount": 0.1, "object": "stuot"},
      {"at": 0, "action": "tilt", "angle": 10, "object": 9}]})", "t.json");
  const Scene flight = resolve_scene_objects({"flight", "", {}, {}});
  try {
    bind_timeline(t, flight);
    FAIL() << "bound";
  } catch (const InputError& e) {
    const std::vector<std::string> lines = lines_of(e.what());
    ASSERT_EQ(lines.size(), 3u) << e.what();
    EXPECT_EQ(lines[0], "t.json: 2 mistakes:");
    EXPECT_NE(lines[1].find("field 'actions[0].object'"), std::string::npos) << e.what();  // file order, not time order
    EXPECT_NE(lines[1].find("did you mean \"stout\""), std::string::npos) << e.what();
    EXPECT_NE(lines[2].find("field 'actions[1].object'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace draught
