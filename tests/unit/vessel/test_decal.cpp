// Decals on the walls (core/vessel/decal): the arc-length table against closed forms, the
// mapping's placement and its sizes on the surface (no stretch on a curved bowl), copies,
// bands that join, and the image as the GPU's layer and the reference sample it.
#include "core/vessel/decal.hpp"

#include "test_common.hpp"
#include "core/math/constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace draught {
namespace {

// A point on the wall (inner or outer) of v at angle a (rad, from +z towards +x) and height y.
glm::dvec3 on_wall(const Vessel& v, bool inner, double a, double y) {
  const double r = inner ? v.inner_radius(y) : v.outer_radius(y);
  return {r * std::sin(a), y, r * std::cos(a)};
}

DecalParams decal(float angle, float height, float width, int repeat = 1) {
  DecalParams d;
  d.file = "test";
  d.angle = angle;
  d.height = height;
  d.width = width;
  d.repeat = repeat;
  return d;
}

TEST(WallArcLengths, OfACylinderAreHeights) {
  const Vessel v = build_vessel(test::simple_glass({{0.03f, 0.0f}, {0.03f, 0.12f}}, 0.003f, 0.01f, 0.0015f));
  const WallArcLengths a = wall_arc_lengths(v);
  for (double y : {0.0, 0.013, 0.06, 0.1199})
    for (bool inner : {false, true}) EXPECT_NEAR(a.at(v, inner, y), y, 1e-12) << y;
}

TEST(WallArcLengths, OfAConeGrowByItsSlantHeight) {
  // r from 0.02 to 0.05 over 0.1 m: every metre up is sqrt(1 + 0.3^2) along the wall.
  const Vessel v = build_vessel(test::simple_glass({{0.02f, 0.0f}, {0.05f, 0.1f}}, 0.003f, 0.01f, 0.0015f));
  const WallArcLengths a = wall_arc_lengths(v);
  const double slant = std::sqrt(1 + 0.3 * 0.3);
  for (double y : {0.01, 0.05, 0.0999}) EXPECT_NEAR(a.at(v, false, y), y * slant, 1e-6) << y;
}

TEST(WallArcLengths, OfATulipFollowTheCurve) {
  const Vessel v = test::preset_vessel("tulip");
  const WallArcLengths a = wall_arc_lengths(v);
  // Increasing, never less than the height gained, and the sum of the segments' lengths.
  double sum = 0;
  for (int k = 0; k < Vessel::kSegments; ++k) {
    sum += std::hypot(v.dy, v.r_outer[size_t(k) + 1] - v.r_outer[size_t(k)]);
    EXPECT_NEAR(a.outer[size_t(k) + 1], sum, 1e-12);
    EXPECT_GE(a.outer[size_t(k) + 1] - a.outer[size_t(k)], v.dy * (1 - 1e-12));
  }
  // The tulip's foot, stem and bowl curve: its wall is longer than the glass is tall.
  EXPECT_GT(a.outer.back(), 1.15 * v.height);
}

TEST(DecalPlacement, CentreAndEdgesOnACylinder) {
  const Vessel v = build_vessel(test::simple_glass({{0.03f, 0.0f}, {0.03f, 0.12f}}, 0.003f, 0.01f, 0.0015f));
  const WallArcLengths arcs = wall_arc_lengths(v);
  // (Parameters are floats: placements agree to their precision.)
  // 40 mm wide at 60 mm up, facing 30 degrees; a 400 x 100 image: 10 mm high.
  const DecalPlacement d = place_decal(v, arcs, decal(30, 0.06f, 0.04f), false, 400, 100);
  ASSERT_TRUE(d.present);
  EXPECT_NEAR(d.extent, 0.01, 1e-6);
  const double a = glm::radians(30.0);
  auto uv = decal_uv(v, arcs, d, on_wall(v, false, a, 0.06));
  ASSERT_TRUE(uv);
  EXPECT_NEAR(uv->x, 0.5, 1e-6);
  EXPECT_NEAR(uv->y, 0.5, 1e-6);
  // A quarter of its width to the right (counter-clockwise seen from above), a quarter of
  // its height up: (0.75, 0.25), v running down the image.
  uv = decal_uv(v, arcs, d, on_wall(v, false, a + 0.01 / 0.03, 0.0625));
  ASSERT_TRUE(uv);
  EXPECT_NEAR(uv->x, 0.75, 1e-6);
  EXPECT_NEAR(uv->y, 0.25, 1e-6);
  // Past its edges there is none; on the far side of the glass neither.
  EXPECT_FALSE(decal_uv(v, arcs, d, on_wall(v, false, a + 0.021 / 0.03, 0.06)));
  EXPECT_FALSE(decal_uv(v, arcs, d, on_wall(v, false, a, 0.066)));
  EXPECT_FALSE(decal_uv(v, arcs, d, on_wall(v, false, a + kPi, 0.06)));
  // No file: no decal.
  DecalParams none = decal(30, 0.06f, 0.04f);
  none.file.clear();
  EXPECT_FALSE(place_decal(v, arcs, none, false, 400, 100).present);
}

TEST(DecalPlacement, KeepsItsPrintedSizeOnACurvedBowl) {
  // Low on the wine glass's bowl the wall slopes at about 50 degrees and curves: the decal
  // is as wide around the wall at every height as it is printed, and as long along the
  // wall as its image's aspect says, which is much more than the height it spans.
  const Vessel v = test::preset_vessel("wine");
  const WallArcLengths arcs = wall_arc_lengths(v);
  const double y = 0.1;
  const DecalPlacement d = place_decal(v, arcs, decal(0, float(y), 0.02f), false, 300, 300);
  ASSERT_NEAR(d.extent, 0.02, 1e-8);
  // Across: u moves by the arc around the wall over the width, whatever the radius there.
  for (double dy : {-0.004, 0.0, 0.004}) {
    const double r = v.outer_radius(y + dy);
    const auto left = decal_uv(v, arcs, d, on_wall(v, false, -0.005 / r, y + dy));
    const auto right = decal_uv(v, arcs, d, on_wall(v, false, 0.005 / r, y + dy));
    ASSERT_TRUE(left && right) << dy;
    EXPECT_NEAR((right->x - left->x) * 0.02, 0.01, 1e-6) << "10 mm around the wall at " << y + dy;
  }
  // Down: top and bottom edges are 20 mm apart along the wall, found by walking it.
  double top = y, bottom = y;
  while (decal_uv(v, arcs, d, on_wall(v, false, 0.0, top + 1e-5))) top += 1e-5;
  while (decal_uv(v, arcs, d, on_wall(v, false, 0.0, bottom - 1e-5))) bottom -= 1e-5;
  double along = 0;
  for (double t = bottom; t < top; t += 1e-5)
    along += std::hypot(1e-5, v.outer_radius(t + 1e-5) - v.outer_radius(t));
  EXPECT_NEAR(along, 0.02, 1e-4);
  EXPECT_LT(top - bottom, 0.016) << "the bowl slopes: the decal spans less height than its length";
}

TEST(DecalPlacement, CopiesAroundTheGlass) {
  const Vessel v = test::preset_vessel("pint");
  const WallArcLengths arcs = wall_arc_lengths(v);
  const DecalPlacement d = place_decal(v, arcs, decal(10, 0.08f, 0.02f, 3), false, 100, 100);
  for (int k = 0; k < 3; ++k) {
    const auto uv = decal_uv(v, arcs, d, on_wall(v, false, glm::radians(10.0 + 120.0 * k), 0.08));
    ASSERT_TRUE(uv) << k;
    EXPECT_NEAR(uv->x, 0.5, 1e-6) << k;
  }
  EXPECT_FALSE(decal_uv(v, arcs, d, on_wall(v, false, glm::radians(70.0), 0.08)));
}

TEST(DecalPlacement, ABandJoinsRoundTheGlass) {
  // Width 0: each of the 4 copies fills a quarter turn at every height, so u runs 0..1
  // across each and wraps where the next begins.
  const Vessel v = test::preset_vessel("tulip");
  const WallArcLengths arcs = wall_arc_lengths(v);
  const DecalPlacement d = place_decal(v, arcs, decal(0, 0.15f, 0.0f, 4), false, 1024, 32);
  const double r = v.outer_radius(0.15);
  EXPECT_NEAR(d.extent, 2 * kPi * r / 4 * 32.0 / 1024.0, 1e-8);
  const double edge = kPi / 4;  // between copy 0 and copy 1
  const auto before = decal_uv(v, arcs, d, on_wall(v, false, edge - 1e-6, 0.15));
  const auto after = decal_uv(v, arcs, d, on_wall(v, false, edge + 1e-6, 0.15));
  ASSERT_TRUE(before && after);
  EXPECT_NEAR(before->x, 1.0, 1e-5);
  EXPECT_NEAR(after->x, 0.0, 1e-5);
  for (double a = -kPi; a < kPi; a += 0.1) EXPECT_TRUE(decal_uv(v, arcs, d, on_wall(v, false, a, 0.15))) << a;
}

TEST(DecalPlacement, TheInnerWallHasItsOwnRadiusAndArcs) {
  const Vessel v = test::preset_vessel("tulip");
  const WallArcLengths arcs = wall_arc_lengths(v);
  const DecalPlacement d = place_decal(v, arcs, decal(0, 0.1f, 0.02f), true, 100, 100);
  EXPECT_TRUE(d.inner);
  EXPECT_NEAR(d.centre_s, arcs.at(v, true, 0.1), 1e-8);
  const double r = v.inner_radius(0.1);
  const auto uv = decal_uv(v, arcs, d, on_wall(v, true, 0.005 / r, 0.1));
  ASSERT_TRUE(uv);
  EXPECT_NEAR(uv->x, 0.75, 1e-6);
}

Image two_texels(std::array<std::uint8_t, 8> rgba) {
  return Image{2, 1, std::vector<std::uint8_t>(rgba.begin(), rgba.end())};
}

TEST(DecalImage, SampledBilinearlyInLinearLightWithAlphaPremultiplied) {
  // White opaque next to transparent black: half way, half the light and half the cover.
  const Image img = two_texels({255, 255, 255, 255, 0, 0, 0, 0});
  glm::dvec4 c = sample_decal_image(img, {0.5, 0.5});
  EXPECT_NEAR(c.a, 0.5, 1e-12);
  EXPECT_NEAR(c.r, 0.5, 1e-12);
  // At a texel's centre, that texel; sRGB 188 is about 0.5 in linear light.
  EXPECT_NEAR(sample_decal_image(img, {0.25, 0.5}).r, 1.0, 1e-12);
  EXPECT_NEAR(sample_decal_image(two_texels({188, 188, 188, 255, 188, 188, 188, 255}), {0.1, 0.1}).g, 0.5029, 1e-3);
  // u wraps: just left of 0 is between the last texel and the first.
  EXPECT_NEAR(sample_decal_image(img, {0.0, 0.5}).a, 0.5, 1e-12);
}

TEST(DecalImage, LayerTexelsKeepFlatColoursAndCoverage) {
  Image flat{5, 3, {}};
  for (int i = 0; i < 15; ++i) flat.rgba.insert(flat.rgba.end(), {200, 120, 40, 255});
  for (int size : {2, 4, 16}) {
    const std::vector<std::uint8_t> t = decal_layer_texels(flat, size);
    ASSERT_EQ(t.size(), size_t(size * size * 4));
    for (size_t i = 0; i < t.size(); i += 4) {
      ASSERT_NEAR(t[i], 200, 1) << size;
      ASSERT_NEAR(t[i + 1], 120, 1);
      ASSERT_NEAR(t[i + 2], 40, 1);
      ASSERT_EQ(t[i + 3], 255);
    }
  }
  // Premultiplied: a red texel beside transparent ones shrinks to red at a part of its
  // cover (stored premultiplied: sRGB of 1 x cover), never darkened towards black.
  Image dot{4, 1, {0, 0, 0, 0, 255, 0, 0, 255, 0, 0, 0, 0, 0, 0, 0, 0}};
  const std::vector<std::uint8_t> t = decal_layer_texels(dot, 1);
  const double cover = t[3] / 255.0;
  EXPECT_NEAR(cover, 0.25, 0.01);
  const double linear_red = std::pow((t[0] / 255.0 + 0.055) / 1.055, 2.4);
  EXPECT_NEAR(linear_red / cover, 1.0, 0.03);
  // A checker of black and white averages to half the light.
  Image checker{2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255}};
  EXPECT_NEAR(decal_layer_texels(checker, 1)[0], 188, 1);
}

}  // namespace
}  // namespace draught
