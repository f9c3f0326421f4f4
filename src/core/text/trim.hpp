// Text without its leading and trailing white space (the point-cloud readers' lines and
// fields).
#pragma once

#include <string_view>

namespace draught {

inline std::string_view trim(std::string_view s) {
  const char* ws = " \t\r\v\f";
  const auto a = s.find_first_not_of(ws);
  if (a == std::string_view::npos) return {};
  return s.substr(a, s.find_last_not_of(ws) - a + 1);
}

}  // namespace draught
