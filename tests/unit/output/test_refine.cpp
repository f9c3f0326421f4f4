// Adaptive supersampling (core/output/refine): which pixels take more samples, and the
// resolve that puts their fine samples in place of their own.
#include "core/output/refine.hpp"

#include "core/output/resolve.hpp"
#include "core/output/tonemap.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace draught {
namespace {

constexpr int kAces = int(Tonemap::Aces);

// A width x height picture of factor x factor samples, every sample grey g (linear).
std::vector<float> flat(int width, int height, int factor, float g) {
  std::vector<float> s;
  for (int i = 0; i < width * height * factor * factor; ++i) s.insert(s.end(), {g, g, g, 1.0f});
  return s;
}

// Sample (i, j) of pixel (x, y) set to grey g (rows top-down, as render reads them back).
void set_sample(std::vector<float>& s, int width, int factor, int x, int y, int i, int j, float g) {
  float* p = &s[(size_t(y * factor + j) * size_t(width * factor) + size_t(x * factor + i)) * 4];
  p[0] = p[1] = p[2] = g;
}

TEST(Refine, AnEvenPictureTakesNoMoreSamples) {
  for (float g : {0.0f, 0.2f, 5.0f})
    EXPECT_TRUE(pixels_to_refine(flat(9, 7, 2, g), 9, 7, 2, kAces, 6.0).empty());
}

TEST(Refine, APixelWhoseSamplesDisagreeIsRefinedWithItsNeighbours) {
  // One sample of pixel (4, 3) catches a bright line: that pixel and the eight round it
  // (a line thinner than the samples' spacing may pass between the neighbours' samples).
  std::vector<float> s = flat(9, 7, 2, 0.2f);
  set_sample(s, 9, 2, 4, 3, 1, 0, 3.0f);
  const std::vector<PixelRun> runs = pixels_to_refine(s, 9, 7, 2, kAces, 6.0);
  const std::vector<PixelRun> expected = {{3, 2, 3}, {3, 3, 3}, {3, 4, 3}};
  EXPECT_EQ(runs, expected);
  EXPECT_EQ(pixels_in(runs), 9);
  // At the picture's corner the neighbours are cut by its edges.
  std::vector<float> c = flat(9, 7, 2, 0.2f);
  set_sample(c, 9, 2, 0, 0, 0, 1, 3.0f);
  const std::vector<PixelRun> corner = {{0, 0, 2}, {0, 1, 2}};
  EXPECT_EQ(pixels_to_refine(c, 9, 7, 2, kAces, 6.0), corner);
}

TEST(Refine, TheThresholdIsInDisplayLevels) {
  // Two samples a few levels apart: refined below their difference, not at or above it.
  std::vector<float> s = flat(3, 3, 2, 0.2f);
  const float brighter = 0.215f;
  set_sample(s, 3, 2, 1, 1, 0, 0, brighter);
  const int levels = display_code(brighter, kAces) - display_code(0.2, kAces);
  ASSERT_GE(levels, 2);
  EXPECT_FALSE(pixels_to_refine(s, 3, 3, 2, kAces, levels - 0.5).empty());
  EXPECT_TRUE(pixels_to_refine(s, 3, 3, 2, kAces, levels).empty());
  // Light far beyond white under the tone map: the same display code, nothing to refine.
  std::vector<float> w = flat(3, 3, 2, 500.0f);
  set_sample(w, 3, 2, 1, 1, 0, 0, 900.0f);
  EXPECT_TRUE(pixels_to_refine(w, 3, 3, 2, kAces, 0.5).empty());
}

TEST(Refine, OneSampleAPixelHasNothingToRefine) {
  std::vector<float> s = flat(4, 4, 1, 0.2f);
  set_sample(s, 4, 1, 2, 2, 0, 0, 3.0f);
  EXPECT_TRUE(pixels_to_refine(s, 4, 4, 1, kAces, 6.0).empty());
}

TEST(Refine, ResolvedPixelsTakeTheMeanOfTheirFineSamples) {
  const std::vector<float> s = flat(4, 3, 2, 0.2f);
  RefinedSamples r;
  r.fine = 3;
  r.runs = {{1, 1, 2}};  // pixels (1, 1) and (2, 1): 3 rows of 6 fine samples
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 6; ++i) {
      const float g = i < 3 ? (i == 0 && j == 0 ? 0.9f : 0.0f) : 0.5f;  // pixel 1: one in nine bright
      r.rgba.insert(r.rgba.end(), {g, g, g, 1.0f});
    }
  const Image out = resolve_refined(s, 4, 3, 2, r, kAces);
  EXPECT_EQ(out.px(1, 1)[0], display_code(0.1, kAces));
  EXPECT_EQ(out.px(2, 1)[0], display_code(0.5, kAces));
  EXPECT_EQ(out.px(2, 1)[3], 255);
  // The others keep their own samples' resolve.
  const Image plain = resolve_linear(s, 4, 3, 2, kAces);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x)
      if (y != 1 || (x != 1 && x != 2)) {
        EXPECT_EQ(out.px(x, y)[0], plain.px(x, y)[0]) << x << ", " << y;
      }
  // No runs: resolve_linear's picture.
  EXPECT_EQ(resolve_refined(s, 4, 3, 2, RefinedSamples{}, kAces).rgba, plain.rgba);
}

TEST(Refine, ATransparentPicturesDisplaySamplesResolveAsItsDownsample) {
  // Premultiplied display codes and coverage (a glass's edge over nothing): decoded, the
  // resolve without a tone map is core/io/image's downsample, and a coverage edge alone
  // (black over transparent: the same colour codes) is refined.
  Image img{4, 2, {}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      const std::uint8_t a = x == 1 && y == 0 ? 0 : 255, v = std::uint8_t(x * 60 + y * 7);
      img.rgba.insert(img.rgba.end(), {v, std::uint8_t(v / 2), 0, a});
    }
  const std::vector<float> s = samples_from_display(img);
  EXPECT_EQ(resolve_linear(s, 2, 1, 2, int(Tonemap::None)).rgba, downsample(img, 2).rgba);
  Image black{4, 2, std::vector<std::uint8_t>(32, 0)};
  for (size_t i = 3; i < black.rgba.size(); i += 4) black.rgba[i] = i == 3 ? 255 : 0;  // one sample covered
  const std::vector<PixelRun> edge = {{0, 0, 2}};
  EXPECT_EQ(pixels_to_refine(samples_from_display(black), 2, 1, 2, int(Tonemap::None), 6.0), edge);
}

TEST(Refine, MismatchedSizesAreRefused) {
  const std::vector<float> s = flat(4, 3, 2, 0.2f);
  EXPECT_THROW(pixels_to_refine(s, 4, 4, 2, kAces, 6.0), std::invalid_argument);
  RefinedSamples r;
  r.fine = 2;
  r.runs = {{3, 0, 2}};  // leaves the picture
  r.rgba.assign(2 * 4 * 4, 0.0f);
  EXPECT_THROW(resolve_refined(s, 4, 3, 2, r, kAces), std::invalid_argument);
  r.runs = {{0, 0, 2}};
  r.rgba.pop_back();  // one value short
  EXPECT_THROW(resolve_refined(s, 4, 3, 2, r, kAces), std::invalid_argument);
}

}  // namespace
}  // namespace draught
