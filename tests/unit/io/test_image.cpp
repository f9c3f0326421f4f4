// Images: the supersampling resolve averages in linear light.
#include "core/io/image.hpp"

#include <gtest/gtest.h>

namespace draught {
namespace {

Image block(std::initializer_list<std::uint8_t> grey, std::uint8_t alpha = 255) {
  Image img{2, 2, {}};
  for (std::uint8_t g : grey) img.rgba.insert(img.rgba.end(), {g, g, g, alpha});
  return img;
}

TEST(Downsample, AveragesInLinearLight) {
  // Half black, half white is half the light: sRGB 188, not the code's mean 128.
  const Image out = downsample(block({0, 255, 255, 0}), 2);
  ASSERT_EQ(out.width, 1);
  ASSERT_EQ(out.height, 1);
  EXPECT_EQ(out.rgba[0], 188);
  EXPECT_EQ(out.rgba[1], 188);
  EXPECT_EQ(out.rgba[2], 188);
  EXPECT_EQ(out.rgba[3], 255);
}

TEST(Downsample, KeepsAFlatColourExactly) {
  for (int g = 0; g < 256; ++g) {
    const Image out = downsample(block({std::uint8_t(g), std::uint8_t(g), std::uint8_t(g), std::uint8_t(g)}, 77), 2);
    ASSERT_EQ(out.rgba[0], g);
    ASSERT_EQ(out.rgba[3], 77);
  }
}

TEST(Downsample, AveragesCoverageLinearly) {
  Image img = block({0, 0, 0, 0});
  img.rgba[3] = 0;
  img.rgba[7] = 255;
  img.rgba[11] = 255;
  img.rgba[15] = 0;
  EXPECT_EQ(downsample(img, 2).rgba[3], 128);
}

TEST(Downsample, FactorOneIsTheImage) {
  const Image in = block({1, 2, 3, 4});
  EXPECT_EQ(downsample(in, 1).rgba, in.rgba);
}

}  // namespace
}  // namespace draught
