// core/math/srgb.hpp: sRGB's transfer function against the standard's figures, each way
// the inverse of the other, continuous where its two pieces meet; its 8-bit codes built
// from it.
#include "core/math/srgb.hpp"

#include <gtest/gtest.h>

namespace draught {
namespace {

TEST(Srgb, MatchesTheStandardsFigures) {
  EXPECT_DOUBLE_EQ(srgb_to_linear(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgb_to_linear(1.0), 1.0);
  EXPECT_NEAR(srgb_to_linear(0.5), 0.214041, 1e-6);    // mid grey's code: a fifth of the light
  EXPECT_NEAR(linear_to_srgb(0.18), 0.461356, 1e-6);   // 18 % grey
  EXPECT_NEAR(linear_to_srgb(0.001), 0.01292, 1e-12);  // the linear piece near black
}

TEST(Srgb, EachWayIsTheOthersInverseAndClamps) {
  for (int i = 0; i <= 1000; ++i) {
    const double x = i / 1000.0;
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(x)), x, 1e-12) << x;
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(x)), x, 1e-12) << x;
  }
  EXPECT_EQ(linear_to_srgb(-0.5), 0.0);
  EXPECT_DOUBLE_EQ(linear_to_srgb(7.0), 1.0);
}

TEST(Srgb, ThePiecesMeetWithoutAStep) {
  EXPECT_NEAR(linear_to_srgb(0.0031308 - 1e-12), linear_to_srgb(0.0031308 + 1e-12), 1e-7);
  EXPECT_NEAR(srgb_to_linear(0.04045 - 1e-12), srgb_to_linear(0.04045 + 1e-12), 1e-7);
}

TEST(Srgb, TheEightBitTablesAreTheFunctions) {
  for (int code = 0; code < 256; ++code) {
    EXPECT_EQ(srgb8_to_linear(std::uint8_t(code)), srgb_to_linear(code / 255.0));
    EXPECT_EQ(linear_to_srgb8(srgb8_to_linear(std::uint8_t(code))), code);  // each code comes back
  }
}

}  // namespace
}  // namespace draught
