// Images: the supersampling resolve averages in linear light.
#include "core/io/image.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace draught {
namespace {

Image block(std::initializer_list<std::uint8_t> grey, std::uint8_t alpha = 255) {
  Image img{2, 2, std::vector<std::uint8_t>(16)};
  size_t i = 0;
  for (std::uint8_t g : grey)
    for (std::uint8_t c : {g, g, g, alpha}) img.rgba[i++] = c;
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

TEST(Downsample, APremultipliedEdgeKeepsItsColour) {
  // Transparent pictures are premultiplied (the shader writes sRGB of radiance already
  // weighted by coverage): one opaque orange sample beside three empty ones resolves to
  // a quarter of its light at a quarter coverage, so un-premultiplied it is orange still,
  // with no dark fringe and no colour bleeding in from the empty samples.
  Image img{2, 2, std::vector<std::uint8_t>(16, 0)};
  const std::uint8_t orange[4] = {255, 140, 30, 255};
  std::copy_n(orange, 4, img.px(0, 0));
  const Image out = downsample(img, 2);
  auto linear = [](int code) {
    const double c = code / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  ASSERT_EQ(out.rgba[3], 64);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(linear(out.rgba[size_t(c)]) / (out.rgba[3] / 255.0), linear(orange[c]), 0.01) << "channel " << c;
}

TEST(Downsample, FactorOneIsTheImage) {
  const Image in = block({1, 2, 3, 4});
  EXPECT_EQ(downsample(in, 1).rgba, in.rgba);
}

}  // namespace
}  // namespace draught
