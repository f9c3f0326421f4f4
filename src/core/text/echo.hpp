// Echoing user input in error messages: what a message repeats back is capped, so a
// megabyte-long value cannot flood a terminal or a web page, and a cut never splits a
// UTF-8 character (a half character makes the text invalid, and JSON or JavaScript
// handlers that receive the message throw on it).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace draught {

// How many bytes of user input an error message repeats, at most: values, and paths
// (whole up to PATH_MAX: a longer one cannot name a file anyway).
inline constexpr std::size_t kEchoBytes = 60;
inline constexpr std::size_t kEchoPathBytes = 4096;

// The longest prefix of `s` of at most `max_bytes` bytes that ends on a UTF-8 character
// boundary (bytes of a broken sequence count as characters of their own).
std::string_view utf8_prefix(std::string_view s, std::size_t max_bytes);

// `s` with every byte that is not part of a well-formed UTF-8 character replaced by
// U+FFFD, so text quoted from a broken file (e.g. a parser's "last read: '...'") is
// valid UTF-8 whatever the input was.
std::string make_valid_utf8(std::string_view s);

// `s` itself when it fits in `max_bytes`, else its UTF-8-safe prefix followed by "..."
// (the result is then at most max_bytes + 3 bytes long).
std::string shorten(std::string_view s, std::size_t max_bytes = kEchoBytes);

// `s` shortened and quoted as a JSON string ("..." with control characters escaped), for
// messages that echo a string value: got "gold".
std::string quote_input(std::string_view s, std::size_t max_bytes = kEchoBytes);

}  // namespace draught
