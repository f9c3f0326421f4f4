// Tilts chain: each starts from where the glass leans when it begins (no snap back to
// upright), in the order they start, and preparing them is one pass over the actions.
#include "core/params/timeline.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace draught {
namespace {

TEST(TimelineTilts, ASecondTiltStartsWhereTheFirstLeftTheGlass) {
  const Timeline t = load_timeline("gentle-tilt");  // 14 deg towards +X, then 10 deg towards 150 deg at 2.4 s
  const glm::dvec2 before = t.lean_at(2.4 - 1e-6), after = t.lean_at(2.4 + 1e-6);
  EXPECT_NEAR(glm::length(before), 14 * kDegree, 1e-9);
  EXPECT_LT(glm::length(after - before), 1e-4) << "the glass must not jump at the start of the second tilt";
  EXPECT_NEAR(glm::length(t.lean_at(4.0)), 10 * kDegree, 1e-9);  // then reaches the second target
  // Smooth everywhere: no step between frames at 240 Hz.
  for (double s = 0; s < 6; s += 1.0 / 240)
    EXPECT_LT(glm::length(t.lean_at(s + 1.0 / 240) - t.lean_at(s)), 0.5 * kDegree) << "at " << s;
}

TEST(TimelineTilts, TiltsChainInStartOrderWhateverTheFileOrder) {
  const std::string head = R"({"draught_timeline": 1, "name": "t", "duration": 4, "actions": [)";
  const Timeline sorted = parse_timeline(head + R"(
      {"at": 0, "action": "tilt", "angle": 20, "toward": 0, "duration": 1},
      {"at": 2, "action": "tilt", "angle": 10, "toward": 90, "duration": 1}]})", "sorted.json");
  const Timeline reversed = parse_timeline(head + R"(
      {"at": 2, "action": "tilt", "angle": 10, "toward": 90, "duration": 1},
      {"at": 0, "action": "tilt", "angle": 20, "toward": 0, "duration": 1}]})", "reversed.json");
  for (double s : {0.5, 1.5, 2.5, 3.5}) EXPECT_EQ(sorted.lean_at(s), reversed.lean_at(s)) << s;
  EXPECT_NEAR(glm::length(sorted.lean_at(1.5)), 20 * kDegree, 1e-12);
}

TEST(TimelineTilts, ManyTiltsLoad) {
  // 20,000 tilts: preparing them used to scan every earlier action for each tilt.
  std::string text = R"({"draught_timeline": 1, "name": "many", "duration": 250, "actions": [)";
  for (int i = 0; i < 20000; ++i)
    text += (i ? "," : "") + std::string(R"({"at": )") + std::to_string(i * 0.01) +
            R"(, "action": "tilt", "angle": )" + std::to_string(i % 30) + R"(, "duration": 0.005})";
  text += "]}";
  const Timeline t = parse_timeline(text, "many.json");
  EXPECT_NEAR(glm::length(t.lean_at(199.998)), 19 * kDegree, 1e-9);
}

}  // namespace
}  // namespace draught
