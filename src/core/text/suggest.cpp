#include "core/text/suggest.hpp"

#include "core/text/echo.hpp"

#include <algorithm>

namespace draught {

std::size_t edit_distance_osa(std::string_view a, std::string_view b) {
  // Optimal string alignment with three rolling rows: O(|a| |b|) time, O(|b|) memory.
  std::vector<std::size_t> prev2(b.size() + 1), prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::optional<std::string> nearest_word(std::string_view word, const std::vector<std::string>& candidates) {
  // Anything much longer than every candidate is no typo of one (and is not worth the
  // quadratic comparison).
  constexpr std::size_t kMaxEdits = 2, kLongest = 256;
  if (word.empty() || word.size() > kLongest) return std::nullopt;
  std::optional<std::string> best;
  std::size_t best_d = kMaxEdits + 1;
  for (const auto& c : candidates) {
    if (c == word) return std::nullopt;  // not a typo
    const std::size_t d = edit_distance_osa(word, c);
    if (d < best_d && 2 * d < word.size()) best_d = d, best = c;
  }
  return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  auto best = nearest_word(word, candidates);
  return best ? " (did you mean '" + *best + "'?)" : "";
}

}  // namespace draught
