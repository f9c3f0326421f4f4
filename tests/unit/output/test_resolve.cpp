// Supersampling's resolve in scene-linear light (core/output/resolve): the samples' light
// is averaged, then tone mapped once, as the reference resolves its paths.
#include "core/output/resolve.hpp"

#include "core/output/tonemap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace draught {
namespace {

constexpr int kResolveAces = int(Tonemap::Aces), kResolveClamp = int(Tonemap::None);

// One pixel of 2 x 2 samples, each grey level g (linear, times the exposure), alpha a.
std::vector<float> quad(std::initializer_list<float> grey, float alpha = 1.0f) {
  std::vector<float> s;
  for (float g : grey) {
    for (int c = 0; c < 3; ++c) s.push_back(g);
    s.push_back(alpha);
  }
  return s;
}

TEST(ResolveLinear, AveragesLightBeforeTheToneMap) {
  // A bright stripe in one sample of four: the pixel shows the tone map of the mean light,
  // brighter than the mean of the tone-mapped samples (the concave curve), as the
  // reference's mean of its paths does.
  const Image out = resolve_linear(quad({4.0f, 0.0f, 0.0f, 0.0f}), 1, 1, 2, kResolveAces);
  ASSERT_EQ(out.width, 1);
  ASSERT_EQ(out.height, 1);
  EXPECT_EQ(out.rgba[0], display_code(1.0, kResolveAces));
  const double per_sample = 0.25 * aces_filmic(4.0);  // averaged after the tone map, as before
  EXPECT_GT(out.rgba[0], std::lround(linear_to_srgb(per_sample) * 255.0) + 10);
  EXPECT_EQ(out.rgba[3], 255);
}

TEST(ResolveLinear, ClampsAfterAveraging) {
  // Without a tone map a sample over 1 is not cut to 1 before the mean: 3 and three 0s are
  // 0.75 of white's light, where clamped first they were 0.25.
  const Image out = resolve_linear(quad({3.0f, 0.0f, 0.0f, 0.0f}), 1, 1, 2, kResolveClamp);
  EXPECT_EQ(out.rgba[0], std::lround(linear_to_srgb(0.75) * 255.0));
}

TEST(ResolveLinear, AFlatPixelIsItsOwnTransform) {
  for (float g : {0.0f, 0.001f, 0.05f, 0.3f, 1.0f, 7.0f, 300.0f})
    for (int t : {kResolveAces, kResolveClamp}) {
      const Image out = resolve_linear(quad({g, g, g, g}, 0.5f), 1, 1, 2, t);
      EXPECT_EQ(out.rgba[0], display_code(g, t)) << g;
      EXPECT_EQ(out.rgba[3], 128) << g;
    }
}

TEST(ResolveLinear, PixelsTakeTheirOwnBlocks) {
  // 2 x 1 pixels of 3 x 3 samples: the left block 0.2 everywhere, the right one 0.8 in one
  // sample only; rows top-down.
  std::vector<float> s(6 * 3 * 4, 0.0f);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) s[size_t(y * 6 + x) * 4] = 0.2f;
  s[size_t(2 * 6 + 5) * 4 + 1] = 0.9f;  // the right pixel's last sample, green
  const Image out = resolve_linear(s, 2, 1, 3, kResolveClamp);
  EXPECT_EQ(out.px(0, 0)[0], display_code(0.2, kResolveClamp));
  EXPECT_EQ(out.px(0, 0)[1], 0);
  EXPECT_EQ(out.px(1, 0)[0], 0);
  EXPECT_EQ(out.px(1, 0)[1], display_code(0.1, kResolveClamp));
}

TEST(ResolveLinear, NonFiniteSamplesCountAsNoLight) {
  const Image out = resolve_linear(quad({INFINITY, NAN, 0.4f, 0.4f}), 1, 1, 2, kResolveAces);
  EXPECT_EQ(out.rgba[0], display_code(0.2, kResolveAces));
}

TEST(ResolveLinear, RefusesSizesThatDoNotMatch) {
  EXPECT_THROW(resolve_linear(quad({1, 1, 1, 1}), 2, 1, 2, kResolveAces), std::invalid_argument);
  EXPECT_THROW(resolve_linear(quad({1, 1, 1, 1}), 1, 1, 0, kResolveAces), std::invalid_argument);
}

}  // namespace
}  // namespace draught
