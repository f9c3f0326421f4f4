// The shared checks of object parameters (core/params/object_params): each mistake's
// message names the file, the field and what was expected, word for word, since the
// droplets' and the point clouds' errors are these.
#include "core/params/object_params.hpp"
#include "test_common.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace draught {
namespace {

const ObjectParamInfo kCount{"count", 1, 32, "", "spheres"};
const ObjectParamInfo kAbsorption{"absorption", 0, 1000, "1/m", "per metre, [r, g, b]"};

using test::input_error_of;

TEST(ObjectParams, IntTakesAWholeNumberInItsRange) {
  EXPECT_EQ(object_param_int(nlohmann::json(1), kCount, "s.json", "o.count"), 1);
  EXPECT_EQ(object_param_int(nlohmann::json(32), kCount, "s.json", "o.count"), 32);
  auto error = [](const char* text) {
    return input_error_of([&] { object_param_int(nlohmann::json::parse(text), kCount, "s.json", "o.count"); });
  };
  for (const char* bad : {"0", "33", "12.5", "\"12\"", "-4"})
    EXPECT_EQ(error(bad), std::string("s.json: field 'o.count': expected a whole number in [1, 32], got ") + bad);
}

TEST(ObjectParams, RgbTakesThreeNumbersEachInItsRange) {
  EXPECT_EQ(object_param_rgb(nlohmann::json::parse("[1, 2.5, 0]"), kAbsorption, "s.json", "o.absorption"),
            glm::vec3(1.0f, 2.5f, 0.0f));
  auto error = [](const char* text) {
    return input_error_of(
        [&] { object_param_rgb(nlohmann::json::parse(text), kAbsorption, "s.json", "o.absorption"); });
  };
  for (const char* bad : {"[1,2]", "[1,2,3,4]", "3", "{\"r\":1}"})
    EXPECT_EQ(error(bad),
              std::string("s.json: field 'o.absorption': expected [r, g, b], each in [0, 1000] (1/m), got ") + bad);
  EXPECT_EQ(error("[1, 2000, 3]"), "s.json: field 'o.absorption': expected a number in [0, 1000] (1/m), got 2000");
  EXPECT_EQ(error("[1, \"red\", 3]"),
            "s.json: field 'o.absorption': expected a number in [0, 1000] (1/m), got \"red\"");
}

}  // namespace
}  // namespace draught
