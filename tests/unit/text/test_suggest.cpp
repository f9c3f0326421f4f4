// "Did you mean": the nearest valid word to a typo, and nothing for words that are not.
#include "core/text/suggest.hpp"

#include <gtest/gtest.h>

namespace draught {
namespace {

TEST(Suggest, EditDistanceCountsSwapsAsOneEdit) {
  EXPECT_EQ(edit_distance_osa("lager", "lager"), 0u);
  EXPECT_EQ(edit_distance_osa("lagr", "lager"), 1u);
  EXPECT_EQ(edit_distance_osa("--fsp", "--fps"), 1u);  // a transposition
  EXPECT_EQ(edit_distance_osa("", "abc"), 3u);
  EXPECT_EQ(edit_distance_osa("kitten", "sitting"), 3u);
}

TEST(Suggest, NearestWordForTypos) {
  const std::vector<std::string> drinks = {"amber-ale", "lager", "pilsner", "stout", "red-wine"};
  EXPECT_EQ(nearest_word("lagr", drinks), "lager");
  EXPECT_EQ(nearest_word("stuot", drinks), "stout");
  EXPECT_EQ(nearest_word("pilsener", drinks), "pilsner");
  const std::vector<std::string> verbs = {"render", "presets", "validate", "params", "bench"};
  EXPECT_EQ(nearest_word("rendr", verbs), "render");
  EXPECT_EQ(nearest_word("valdiate", verbs), "validate");
}

TEST(Suggest, NoSuggestionForUnrelatedOrExactWords) {
  const std::vector<std::string> verbs = {"render", "presets", "validate", "params", "bench"};
  EXPECT_EQ(nearest_word("x", verbs), std::nullopt);  // one letter is no typo of a word
  EXPECT_EQ(nearest_word("coffee", verbs), std::nullopt);
  EXPECT_EQ(nearest_word("render", verbs), std::nullopt);
  EXPECT_EQ(nearest_word(std::string(100000, 'r'), verbs), std::nullopt);  // and fast
  EXPECT_EQ(did_you_mean("coffee", verbs), "");
  EXPECT_EQ(did_you_mean("bnech", verbs), " (did you mean 'bench'?)");
}

}  // namespace
}  // namespace draught
