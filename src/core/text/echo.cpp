#include "core/text/echo.hpp"

#include <cstdio>

namespace draught {

namespace {

// Length of the UTF-8 sequence a lead byte announces; 1 for anything that cannot lead
// one (ASCII, a stray continuation byte, an invalid byte), so each is its own unit.
std::size_t sequence_length(unsigned char c) {
  if (c >= 0xC2 && c <= 0xDF) return 2;
  if (c >= 0xE0 && c <= 0xEF) return 3;
  if (c >= 0xF0 && c <= 0xF4) return 4;
  return 1;
}

bool is_continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

}  // namespace

std::string_view utf8_prefix(std::string_view s, std::size_t max_bytes) {
  std::size_t end = 0;
  while (end < s.size()) {
    std::size_t n = sequence_length(static_cast<unsigned char>(s[end]));
    // A truncated or malformed sequence: take its lead byte alone.
    for (std::size_t k = 1; k < n; ++k)
      if (end + k >= s.size() || !is_continuation(static_cast<unsigned char>(s[end + k]))) n = 1;
    if (end + n > max_bytes) break;
    end += n;
  }
  return s.substr(0, end);
}

std::string make_valid_utf8(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = sequence_length(c);
    bool ok = c < 0x80 || n > 1;
    for (std::size_t k = 1; ok && k < n; ++k)
      ok = i + k < s.size() && is_continuation(static_cast<unsigned char>(s[i + k]));
    // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8 either.
    if (ok && n == 3) {
      const auto c1 = static_cast<unsigned char>(s[i + 1]);
      ok = !(c == 0xE0 && c1 < 0xA0) && !(c == 0xED && c1 >= 0xA0);
    }
    if (ok && n == 4) {
      const auto c1 = static_cast<unsigned char>(s[i + 1]);
      ok = !(c == 0xF0 && c1 < 0x90) && !(c == 0xF4 && c1 >= 0x90);
    }
    if (ok) {
      out.append(s.substr(i, n));
      i += n;
    } else {
      out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
      ++i;
    }
  }
  return out;
}

std::string shorten(std::string_view s, std::size_t max_bytes) {
  if (s.size() <= max_bytes) return std::string(s);
  return std::string(utf8_prefix(s, max_bytes)) + "...";
}

std::string quote_input(std::string_view s, std::size_t max_bytes) {
  const bool cut = s.size() > max_bytes;
  std::string out = "\"";
  for (char ch : cut ? utf8_prefix(s, max_bytes) : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7F) {  // never send terminal control codes through
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out + (cut ? "...\"" : "\"");
}

}  // namespace draught
