// The CLI suite's regular expressions in one file (see cli_helpers.hpp).
#include "cli_helpers.hpp"

#include <regex>

namespace draught_cli_test {

bool matches(const std::string& text, const std::string& pattern) { return std::regex_search(text, std::regex(pattern)); }

std::string first_group(const std::string& text, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(pattern)) && m.size() > 1 ? m[1].str() : std::string();
}

std::string literal_pattern(const std::string& literal) {
  return std::regex_replace(literal, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
}

}  // namespace draught_cli_test
