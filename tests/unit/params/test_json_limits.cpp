// Hostile JSON: deep nesting, huge values and long keys get a clear InputError naming
// the file and the field, and nothing recursive runs deep enough to overflow the stack.
#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/text/echo.hpp"

#include <gtest/gtest.h>

#include <string>

namespace draught {
namespace {

std::string nested_arrays(size_t depth, const std::string& inner = "1") {
  return std::string(depth, '[') + inner + std::string(depth, ']');
}

std::string preset_with(const std::string& field, const std::string& value) {
  return R"({ "draught_preset": 1, "kind": "drink", "name": "x", )" + field + ": " + value + " }";
}

// The InputError message of parsing `text` as a preset ("" when it is accepted).
std::string preset_error(const std::string& text) {
  try {
    parse_preset(text, "deep.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& s, const std::string& needle) { return s.find(needle) != std::string::npos; }

TEST(JsonLimits, DeepArraysInADescriptionAreRefusedNamingTheField) {
  // 100,000 levels overflowed the stack in the release build's error message.
  const std::string e = preset_error(preset_with("\"description\"", nested_arrays(100000)));
  EXPECT_TRUE(has(e, "deep.json: field 'description': nested more than 256 levels deep")) << e;
  EXPECT_LT(e.size(), 300u) << e;
}

TEST(JsonLimits, DeepValueOfAParameterNamesItsPath) {
  const std::string e =
      preset_error(preset_with("\"params\"", R"({ "liquid": { "fill": )" + nested_arrays(5000) + " } }"));
  EXPECT_TRUE(has(e, "deep.json: field 'params.liquid.fill': nested more than 256")) << e;
}

TEST(JsonLimits, DeepObjectsAndTopLevelArrays) {
  std::string objects;
  for (int i = 0; i < 300; ++i) objects += "{\"a\":";
  objects += "1" + std::string(300, '}');
  const std::string e = preset_error(objects);
  EXPECT_TRUE(has(e, "deep.json: field 'a.a.a.a")) << e;
  EXPECT_TRUE(has(e, "256")) << e;
  EXPECT_LT(e.size(), 400u) << e;
  const std::string top = preset_error(nested_arrays(1000));
  EXPECT_TRUE(has(top, "deep.json: nested more than 256 levels deep")) << top;
}

TEST(JsonLimits, DeepValueInATimelineActionNamesTheAction) {
  const std::string text = R"({ "draught_timeline": 1, "actions": [ { "at": 0, "action": "pour" },
      { "at": 1, "action": "set", "param": "liquid.srm", "value": )" +
                           nested_arrays(10000) + " } ] }";
  try {
    parse_timeline(text, "t.json");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.what(), "t.json: field 'actions[1].value': nested more than 256")) << e.what();
  }
}

TEST(JsonLimits, NestingUpToTheLimitIsParsedAndEchoedShort) {
  // 255 levels inside the top-level object: within the limit, so the loader's own
  // check reports it, echoing a capped value.
  const std::string e = preset_error(preset_with("\"description\"", nested_arrays(255)));
  EXPECT_TRUE(has(e, "deep.json: field 'description': expected a string, got [[[[")) << e;
  EXPECT_TRUE(e.ends_with("...")) << e;
  EXPECT_LT(e.size(), 120u) << e;
  EXPECT_TRUE(has(preset_error(preset_with("\"description\"", nested_arrays(256))), "nested more than 256"));
}

TEST(JsonLimits, LongKeysAreRefusedBeforeTheyAreEchoed) {
  const std::string key(100000, 'k');
  const std::string e = preset_error(preset_with("\"params\"", R"({ "liquid": { ")" + key + R"(": 1 } })"));
  EXPECT_TRUE(has(e, "deep.json: field 'params.liquid.kkkk")) << e.substr(0, 300);
  EXPECT_TRUE(has(e, "a key of 100000 bytes")) << e.substr(0, 300);
  EXPECT_TRUE(has(e, "limit of 128 bytes")) << e.substr(0, 300);
  EXPECT_LT(e.size(), 400u);
  // A key at the limit is just an unknown key.
  const std::string ok =
      preset_error(preset_with("\"params\"", R"({ "liquid": { ")" + std::string(128, 'k') + R"(": 1 } })"));
  EXPECT_TRUE(has(ok, "unknown parameter")) << ok.substr(0, 300);
}

TEST(JsonLimits, HugeStringValuesAreEchoedCappedAndWhole) {
  std::string beers;
  for (int i = 0; i < 200000; ++i) beers += "\xF0\x9F\x8D\xBA";  // a 4-byte character, 800 kB
  for (const char* field : {"\"kind\"", "\"name\""}) {
    const std::string e = preset_error(preset_with(field, "[\"" + beers + "\"]"));
    EXPECT_TRUE(has(e, "deep.json: field ")) << e.substr(0, 200);
    EXPECT_LT(e.size(), 200u) << "echoed the whole value";
    // The last character before "..." is a whole beer glass.
    const auto cut = e.rfind("...");
    ASSERT_NE(cut, std::string::npos) << e;
    EXPECT_EQ(e.substr(cut - 4, 4), "\xF0\x9F\x8D\xBA") << "a UTF-8 character was cut";
  }
  // A string of the wrong value for `kind` is quoted and capped too.
  const std::string k = preset_error(R"({ "kind": ")" + beers + R"(", "name": "x" })");
  EXPECT_TRUE(has(k, "field 'kind': expected \"glass\"")) << k.substr(0, 200);
  EXPECT_LT(k.size(), 200u);
}

TEST(JsonLimits, MalformedJsonMessagesAreCappedAndValidUtf8) {
  // The parser quotes the token it was reading: here a 1 MB string with a bad byte at
  // its end, and a lone invalid byte.
  const std::string e = preset_error("{ \"name\": \"" + std::string(1 << 20, 'x') + "\xFF\" }");
  EXPECT_TRUE(has(e, "deep.json:1:")) << e.substr(0, 300);
  EXPECT_TRUE(has(e, "malformed JSON")) << e.substr(0, 300);
  EXPECT_LT(e.size(), 400u) << e.substr(0, 300);
  EXPECT_EQ(make_valid_utf8(e), e) << "not valid UTF-8: " << e;
  const std::string b = preset_error("{ \"kind\": \xC3 }");
  EXPECT_TRUE(has(b, "malformed JSON")) << b;
  EXPECT_EQ(make_valid_utf8(b), b) << "not valid UTF-8: " << b;
}

TEST(JsonLimits, ShortDumpIsBoundedWhateverTheValue) {
  // Built in memory (as the web page can), deeper than any parser would allow.
  nlohmann::json deep = 1;
  for (int i = 0; i < 20000; ++i) deep = nlohmann::json::array({std::move(deep)});
  const std::string d = short_dump(deep);
  EXPECT_EQ(d, std::string(57, '[') + "...");
  EXPECT_EQ(short_dump(nlohmann::json{{"a", 1}}), "{\"a\":1}");
  EXPECT_EQ(short_dump(nlohmann::json("half")), "\"half\"");
  const std::string big = short_dump(nlohmann::json(std::string(1 << 20, 'x')));
  EXPECT_EQ(big.size(), kEchoBytes);
  EXPECT_TRUE(big.ends_with("x..."));
}

}  // namespace
}  // namespace draught
