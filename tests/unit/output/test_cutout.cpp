// Transparent pictures (core/output/cutout): the light behind the objects, and the PNG's
// straight alpha made from the renderer's premultiplied samples.
#include "core/output/cutout.hpp"

#include "core/output/tonemap.hpp"
#include "core/params/preset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace draught {
namespace {

Image one_pixel(int r, int g, int b, int a) {
  return Image{1, 1, {std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), std::uint8_t(a)}};
}

// Linear light of an sRGB code.
double lin(int code) { return srgb_to_linear(code / 255.0); }

TEST(StraightAlpha, OverBlackThePixelKeepsItsLight) {
  // Premultiplied samples of every kind: opaque, half covered, faint, a lager's gold.
  const int cases[][4] = {{200, 150, 40, 255}, {90, 60, 20, 128}, {30, 30, 30, 20}, {211, 168, 0, 247}, {12, 5, 0, 200}};
  for (const auto& c : cases) {
    const Image s = straight_alpha(one_pixel(c[0], c[1], c[2], c[3]));
    const double a = s.rgba[3] / 255.0;
    EXPECT_EQ(s.rgba[3], c[3]) << "no channel above coverage: alpha kept";
    for (int k = 0; k < 3; ++k) {
      // Straight colour times alpha is the light the premultiplied sample held (within
      // the rounding of one code of the straight colour, scaled by alpha, and of alpha).
      const double back = lin(s.rgba[size_t(k)]) * a, want = lin(c[k]);
      EXPECT_NEAR(back, want, 0.01 * want + 0.004) << c[0] << " " << c[1] << " " << c[2] << " " << c[3];
    }
  }
}

TEST(StraightAlpha, OpaquePixelsAreUnchanged) {
  Image img{256, 1, {}};
  for (int i = 0; i < 256; ++i) img.rgba.insert(img.rgba.end(), {std::uint8_t(i), std::uint8_t(255 - i), std::uint8_t(i / 2), 255});
  EXPECT_EQ(straight_alpha(img).rgba, img.rgba);
}

TEST(StraightAlpha, LightBeyondCoverageRaisesAlpha) {
  // A highlight on clear glass: much light, little coverage. Straight colour cannot exceed
  // 1, so alpha rises to the brightest channel; over black the light is the same.
  const Image s = straight_alpha(one_pixel(230, 200, 180, 30));
  const double a = s.rgba[3] / 255.0;
  EXPECT_NEAR(a, lin(230), 0.5 / 255);
  EXPECT_EQ(s.rgba[0], 255);
  EXPECT_NEAR(lin(s.rgba[1]) * a, lin(200), 0.004);
  EXPECT_NEAR(lin(s.rgba[2]) * a, lin(180), 0.004);
}

TEST(StraightAlpha, NothingCoveredIsClear) {
  EXPECT_EQ(straight_alpha(one_pixel(0, 0, 0, 0)).rgba, one_pixel(0, 0, 0, 0).rgba);
  EXPECT_EQ(straight_alpha(one_pixel(0, 0, 0, 90)).rgba, one_pixel(0, 0, 0, 90).rgba);  // black glass
}

TEST(StraightAlpha, PngPictureConvertsOnlyTransparentPictures) {
  const Image p = one_pixel(90, 60, 20, 128);
  EXPECT_EQ(png_picture(p, false).rgba, p.rgba);
  EXPECT_NE(png_picture(p, true).rgba, p.rgba);
}

FrameState pint(std::vector<std::string> sets) {
  sets.insert(sets.end(), {"render.transparent=true", "bubbles.max_bubbles=0"});
  return make_frame(resolve_scene({"lager", "pint", sets, {}}));
}

TEST(CutoutLight, IsTheLitSweepBehindTheGlass) {
  const FrameState f = pint({});
  ASSERT_TRUE(f.backdrop.present);
  const glm::dvec3 L = cutout_light(f);
  // The sweep behind the pint, lit by the key, the strips and the sky: a bright, nearly
  // neutral grey (the studio's paper), not the dark sky of the studio's ceiling.
  EXPECT_GT(L.g, 0.3);
  EXPECT_LT(std::abs(L.r - L.g), 0.1 * L.g);
  EXPECT_LT(std::abs(L.b - L.g), 0.1 * L.g);
  // Its albedo over pi times the rig's and the sky's irradiance where the line meets it.
  const glm::dvec3 eye(f.camera.eye), d = glm::normalize(surroundings_centre(f) - eye);
  double t;
  glm::dvec3 n;
  ASSERT_TRUE(f.backdrop.intersect(eye, d, 0.0, t, n));
  const glm::dvec3 p = eye + t * d;
  const glm::dvec3 want = f.backdrop.albedo(p) * (f.lights.irradiance(p, n) + f.environment.sky.at(n)) / std::numbers::pi;
  EXPECT_NEAR(L.g, want.g, 1e-9);
  // A brighter key, brighter light behind.
  const glm::dvec3 brighter = cutout_light(pint({"light.power=12"}));
  EXPECT_GT(brighter.g, L.g * 1.1);  // (the key is one of the lights behind the glass)
}

TEST(CutoutLight, WithoutABackdropIsTheSkyBehind) {
  const FrameState f = pint({"env.floor=false"});
  const glm::dvec3 eye(f.camera.eye), d = glm::normalize(surroundings_centre(f) - eye);
  const glm::dvec3 L = cutout_light(f);
  EXPECT_NEAR(L.g, f.environment.sky.at(d).g / std::numbers::pi, 1e-9);
  EXPECT_TRUE(std::isfinite(L.r) && L.r >= 0 && L.g >= 0 && L.b >= 0);
}

}  // namespace
}  // namespace draught
