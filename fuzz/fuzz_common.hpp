// What every loader must do with any input: accept it, or throw InputError whose message
// names the file, is bounded in length (lines of at most 1 KiB, at most 22 of them) and
// is valid UTF-8. Anything else (another exception, a crash, a sanitizer report, a hang)
// is a finding.
#pragma once

#include "core/io/files.hpp"
#include "core/text/echo.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace draught::fuzz {

inline constexpr const char* kFile = "fuzz.json";

// Aborts (a finding for libFuzzer) with the reason and the message.
[[noreturn]] inline void finding(const char* why, const std::string& message) {
  std::fprintf(stderr, "finding: %s\nmessage (%zu bytes): %.2000s\n", why, message.size(), message.c_str());
  std::abort();
}

inline void check_error(const InputError& e) {
  const std::string m = e.what();
  if (m.find(kFile) == std::string::npos) finding("the error does not name the file", m);
  // Several mistakes are listed one per line (at most 20, a heading and "and N more").
  size_t lines = 0;
  for (size_t start = 0; start <= m.size(); ++lines) {
    size_t end = m.find('\n', start);
    if (end == std::string::npos) end = m.size();
    if (end - start > 1024) finding("a line of the error is longer than 1 KiB (an uncapped echo?)", m);
    start = end + 1;
  }
  if (lines > 22) finding("the error lists more than 20 mistakes", m);
  if (make_valid_utf8(m) != m) finding("the error is not valid UTF-8", m);
}

}  // namespace draught::fuzz
