// "Did you mean ...?": the nearest valid word to a mistyped one (verbs, flags, preset
// and glass names, parameter paths).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace draught {

// Edits (insert, delete, substitute, swap two neighbours) that turn a into b.
std::size_t edit_distance_osa(std::string_view a, std::string_view b);

// The candidate closest to `word`, if one is close enough to be a typo of it: at most 2
// edits, and fewer than half the word's length (so "x" does not suggest "render").
std::optional<std::string> nearest_word(std::string_view word, const std::vector<std::string>& candidates);

// " (did you mean 'lager'?)" or "" when nothing is close.
std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace draught
