// Echoed input in error messages: capped, and never cut inside a UTF-8 character.
#include "../../support/utf8.hpp"
#include "core/text/echo.hpp"

#include <gtest/gtest.h>

#include <string>

namespace draught {
namespace {

using test::valid_utf8;

TEST(Echo, Utf8PrefixNeverSplitsACharacter) {
  // 1-, 2-, 3- and 4-byte characters in a row, cut at every length.
  const std::string s =
      "a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x8D\xBA"
      "b\xC3\xA9\xE2\x82\xAC\xF0\x9F\x8D\xBA";  // aé€🍺bé€🍺
  ASSERT_TRUE(valid_utf8(s));
  for (size_t n = 0; n <= s.size() + 1; ++n) {
    const std::string_view p = utf8_prefix(s, n);
    EXPECT_LE(p.size(), n);
    EXPECT_TRUE(valid_utf8(p)) << "cut at " << n;
    EXPECT_EQ(s.substr(0, p.size()), p);
  }
  EXPECT_EQ(utf8_prefix(s, 2), "a");  // not "a" + half of é
  EXPECT_EQ(utf8_prefix(s, 3), "a\xC3\xA9");
  EXPECT_EQ(utf8_prefix(s, 9), "a\xC3\xA9\xE2\x82\xAC");  // the beer glass needs 4 more
}

TEST(Echo, BrokenBytesCountAsTheirOwnCharacters) {
  // A stray continuation byte and a truncated sequence are kept byte by byte, so input
  // that is not UTF-8 is cut like ASCII rather than swallowed.
  const std::string s = "x\x80y\xE2\x82";
  EXPECT_EQ(utf8_prefix(s, 2), "x\x80");
  EXPECT_EQ(utf8_prefix(s, 5), s);
}

TEST(Echo, MakeValidUtf8ReplacesWhatIsNotUtf8) {
  const std::string ok = "a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x8D\xBA";
  EXPECT_EQ(make_valid_utf8(ok), ok);
  const std::string fffd = "\xEF\xBF\xBD";
  EXPECT_EQ(make_valid_utf8("x\xFFy"), "x" + fffd + "y");
  EXPECT_EQ(make_valid_utf8("\x80"), fffd);                                   // a stray continuation byte
  EXPECT_EQ(make_valid_utf8("e\xE2\x82"), "e" + fffd + fffd);                 // a truncated euro sign
  EXPECT_EQ(make_valid_utf8("\xC0\xAF"), fffd + fffd);                        // an overlong '/'
  EXPECT_EQ(make_valid_utf8("\xED\xA0\x80"), fffd + fffd + fffd);             // a UTF-16 surrogate
  EXPECT_EQ(make_valid_utf8("\xF4\x90\x80\x80"), fffd + fffd + fffd + fffd);  // past U+10FFFF
  for (int b = 0; b < 256; ++b) EXPECT_TRUE(valid_utf8(make_valid_utf8(std::string(1, char(b)) + "\xE2"))) << b;
}

TEST(Echo, ShortenCapsAndMarksTheCut) {
  EXPECT_EQ(shorten("short"), "short");
  const std::string euros(100, 'x');
  EXPECT_EQ(shorten(euros, 10), "xxxxxxxxxx...");
  std::string multi;
  for (int i = 0; i < 100; ++i) multi += "\xE2\x82\xAC";  // €, 3 bytes
  const std::string s = shorten(multi);
  EXPECT_TRUE(valid_utf8(s));
  EXPECT_LE(s.size(), kEchoBytes + 3);
  EXPECT_TRUE(s.ends_with("\xE2\x82\xAC...")) << s;
}

TEST(Echo, QuoteInputEscapesControlCharactersAndCaps) {
  EXPECT_EQ(quote_input("gold"), "\"gold\"");
  EXPECT_EQ(quote_input("a\"b\\c"), "\"a\\\"b\\\\c\"");
  // A terminal escape sequence is shown, not sent.
  EXPECT_EQ(quote_input("\x1b[2Jx\n"), "\"\\u001b[2Jx\\u000a\"");
  const std::string q = quote_input(std::string(1 << 20, 'z'));
  EXPECT_EQ(q.size(), 1 + kEchoBytes + 3 + 1);
  EXPECT_TRUE(q.ends_with("zzz...\""));
}

}  // namespace
}  // namespace draught
