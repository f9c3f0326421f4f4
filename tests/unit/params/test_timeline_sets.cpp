// A timeline's set actions blend onto their end value exactly, and rounding on the way
// never takes a value outside its parameter's range (what validate accepts renders).
#include "core/params/timeline.hpp"

#include <gtest/gtest.h>

#include <string>

namespace draught {
namespace {

TEST(TimelineSets, BlendsToAnExactMinimumStayInRange) {
  const Timeline t = parse_timeline(R"({"draught_timeline": 1, "name": "t", "duration": 2, "actions": [
      {"at": 0, "action": "set", "param": "liquid.slosh_damping", "value": 0.005, "duration": 1},
      {"at": 0, "action": "set", "param": "liquid.haze_color", "value": [1, 0, 1], "duration": 1}]})",
                                    "t.json");
  Params base = default_params();
  base.liquid.slosh_damping = 0.05f;
  base.liquid.haze_color = glm::vec3(0.05f, 0.95f, 0.3f);
  for (int i = 0; i <= 2400; ++i) {
    const double s = i / 1200.0;
    Params p;
    ASSERT_NO_THROW(p = t.params_at(s, base)) << "at " << s;
    EXPECT_GE(p.liquid.slosh_damping, 0.005f);
    EXPECT_GE(p.liquid.haze_color.y, 0.0f);
    EXPECT_LE(p.liquid.haze_color.x, 1.0f);
  }
  EXPECT_EQ(t.params_at(1.0, base).liquid.slosh_damping, 0.005f);  // exactly the end value
  EXPECT_EQ(t.params_at(1.5, base).liquid.haze_color, glm::vec3(1, 0, 1));
}

}  // namespace
}  // namespace draught
