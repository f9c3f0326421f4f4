// The backdrop's light map: (x, s) and the backdrop point are inverses of each other on
// floor, curve and wall; the map holds the rig's exact irradiance at its texel centres and,
// filtered between them, stays within one 8-bit step of the exact sum after the tone map
// over the whole map, for the default pint, the checker studio and the flight.
#include "core/environment/backdrop_light.hpp"
#include "core/math/random.hpp"
#include "core/output/tonemap.hpp"
#include "core/params/preset.hpp"
#include "core/scene/motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace draught {
namespace {

TEST(BackdropLight, CoordsAndPointsAreInverses) {
  EnvParams e;
  e.sweep_distance = 0.3f;
  e.sweep_radius = 0.2f;
  const BackdropSurface b = backdrop_surface(e, {0.0, 0.07, 0.1});
  for (double s : {-0.5, -0.01, 0.0, 0.05, 0.2, 0.31, 0.32, 0.5, 1.2}) {
    glm::dvec3 n;
    const glm::dvec3 p = backdrop_point(b, {0.3, s}, n);
    const glm::dvec2 xs = backdrop_coords(b, p);
    EXPECT_NEAR(xs.x, 0.3, 1e-12);
    EXPECT_NEAR(xs.y, s, 1e-12) << "s = " << s;
    // The point lies on the backdrop, with its normal: a ray along -n meets it there.
    double t;
    glm::dvec3 hit_n;
    ASSERT_TRUE(b.intersect(p + 0.01 * n, -n, 0, t, hit_n)) << "s = " << s;
    EXPECT_NEAR(t, 0.01, 1e-9) << "s = " << s;
    EXPECT_NEAR(glm::length(hit_n - n), 0.0, 1e-6) << "s = " << s;
  }
  // s runs on continuously from the floor into the curve and from the curve up the wall.
  glm::dvec3 n;
  EXPECT_NEAR(glm::length(backdrop_point(b, {0, -1e-9}, n) - backdrop_point(b, {0, 1e-9}, n)), 0, 1e-8);
  const double wall = b.radius * std::numbers::pi / 2;
  EXPECT_NEAR(glm::length(backdrop_point(b, {0, wall - 1e-9}, n) - backdrop_point(b, {0, wall + 1e-9}, n)), 0, 1e-8);
}

// The tone-mapped display value (0..255, continuous) of a backdrop of albedo `albedo`
// receiving irradiance e.
double display(double albedo, double e, const RenderParams& r) {
  double c = albedo / std::numbers::pi * e * r.exposure;
  if (r.tonemap == int(Tonemap::Aces)) c = aces_filmic(c);
  return 255.0 * linear_to_srgb(c);
}

// The largest difference (8-bit steps) between the map and the exact sum over random
// points of the map, half of them at texel-cell middles, where filtering errs most; where
// the map distrusts itself the picture takes the exact sum (`trust` false: the map anyway).
double worst_step(const FrameState& f, const BackdropLightMap& m, int points, bool trust = true) {
  const RenderParams& r = f.params.render;
  const double albedo = f.backdrop.kind == Backdrop::Sweep ? std::max({f.backdrop.sweep_albedo.x, f.backdrop.sweep_albedo.y, f.backdrop.sweep_albedo.z})
                                                           : std::max(f.backdrop.floor_a.x, f.backdrop.floor_b.x);
  Rng rng(7, 0, 0);
  const glm::dvec2 texel = m.size / glm::dvec2(m.width, m.height);
  double worst = 0;
  for (int k = 0; k < points; ++k) {
    const double v = rng.uniform(), u = rng.uniform();  // (drawn in this order)
    glm::dvec2 xs = m.origin + texel * 0.5 + glm::dvec2(u, v) * (m.size - texel);
    if (k % 2) xs = m.origin + (glm::floor((xs - m.origin) / texel - 0.5) + 1.0) * texel;  // a cell's middle
    if (!m.covers(xs)) continue;
    glm::dvec3 n;
    const glm::dvec3 p = backdrop_point(f.backdrop, xs, n);
    const glm::dvec4 filtered = m.sample(xs);
    const glm::dvec3 exact = f.lights.irradiance(p, n);
    const glm::dvec3 got = trust && filtered.a < 0.999 ? exact : glm::dvec3(filtered);
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(display(albedo, got[c], r) - display(albedo, exact[c], r)));
  }
  return worst;
}

TEST(BackdropLight, TexelCentresHoldTheExactSum) {
  const FrameState f = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  BackdropLightSettings s;
  s.texel = 0.05;  // coarse: only the centres are checked here
  const BackdropLightMap m = compute_backdrop_light(f, s);
  ASSERT_FALSE(m.empty());
  for (int j = 0; j < m.height; j += 7)
    for (int i = 0; i < m.width; i += 5) {
      glm::dvec3 n;
      const glm::dvec3 p = backdrop_point(f.backdrop, m.texel_centre(i, j), n);
      const glm::dvec3 exact = f.lights.irradiance(p, n);
      const glm::vec3 got = m.irradiance[size_t(j) * size_t(m.width) + size_t(i)];
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], exact[c], 1e-5 * (1 + exact[c]));
      // The sample at a centre is that texel.
      const glm::dvec4 at = m.sample(m.texel_centre(i, j));
      EXPECT_NEAR(at.x, got.x, 1e-5 * (1 + got.x));
    }
}

TEST(BackdropLight, WithinOneStepOfTheExactSumAfterTheToneMap) {
  struct Case {
    const char* name;
    FrameState f;
  };
  std::vector<Case> cases;
  cases.push_back({"default pint", make_frame(resolve_scene({"lager", "pint", {}, {}}))});
  cases.push_back({"checker studio", make_frame(resolve_scene({"checker-studio", "pint", {}, {}}))});
  cases.push_back({"flight", make_frame(resolve_scene_objects({"flight", "", {}, {}}))});
  for (const Case& c : cases) {
    const BackdropLightMap m = compute_backdrop_light(c.f);
    ASSERT_FALSE(m.empty()) << c.name;
    const double worst = worst_step(c.f, m, 200000);
    std::printf("%s: %d x %d texels (%.3f %% left to the exact sum), largest |map - exact| %.3f of an 8-bit step\n",
                c.name, m.width, m.height, 100 * m.untrusted_fraction(), worst);
    // (The strips and the backlight stand through the paper, the lights' planes cross it:
    // steps and kinks in the light that filtering cannot follow, about 0.5 % of the default map.)
    EXPECT_LT(m.untrusted_fraction(), 0.015) << c.name << ": the map leaves too much to the exact sum";
    EXPECT_LT(worst, 1.0) << c.name;
  }
  // Without the exact sum where the map distrusts itself (the strips stand through the
  // sweep's curve: their edge there is a step in the light), it errs by many steps: the
  // test can fail.
  const double worst = worst_step(cases[0].f, compute_backdrop_light(cases[0].f), 200000, false);
  std::printf("default pint, the map everywhere: %.3f\n", worst);
  EXPECT_GT(worst, 1.0);
}

// A thumbnail's map (backdrop_light_texel): up to eight times the texel; the trust marks
// keep it as exact, handing more of it to the exact sum.
TEST(BackdropLight, TheCoarsestTexelIsWithinOneStepToo) {
  std::vector<std::pair<const char*, FrameState>> cases = {
      {"default pint", make_frame(resolve_scene({"lager", "pint", {}, {}}))},
      {"checker studio", make_frame(resolve_scene({"checker-studio", "pint", {}, {}}))},
      {"flight", make_frame(resolve_scene_objects({"flight", "", {}, {}}))}};
  for (const auto& [name, f] : cases) {
    BackdropLightSettings s;
    s.texel = 8 * BackdropLightSettings{}.texel;
    const BackdropLightMap m = compute_backdrop_light(f, s);
    ASSERT_FALSE(m.empty()) << name;
    const double worst = worst_step(f, m, 100000);
    std::printf("%s at %.0f mm: %d x %d texels (%.3f %% left to the exact sum), largest |map - exact| %.3f of an 8-bit step\n",
                name, 1000 * s.texel, m.width, m.height, 100 * m.untrusted_fraction(), worst);
    EXPECT_LT(m.untrusted_fraction(), 0.15) << name;
    EXPECT_LT(worst, 1.0) << name;
  }
}

TEST(BackdropLight, TheTexelFollowsThePicturesPixelsAtTheAim) {
  const FrameState f = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  const double finest = BackdropLightSettings{}.texel;
  EXPECT_EQ(backdrop_light_texel(f, 512, 512), finest);
  EXPECT_EQ(backdrop_light_texel(f, 16, 16), 8 * finest);  // a 16 px pint: pixels of about 1.5 cm
  EXPECT_EQ(backdrop_light_texel(f, 4, 4), 8 * finest);    // never coarser than 4 cm
  double last = 1e9;
  for (int h : {8, 16, 24, 32, 48, 64, 96, 128, 256, 1024}) {
    const double t = backdrop_light_texel(f, h, h);
    EXPECT_LE(t, last) << h << " px";
    EXPECT_GE(t, finest) << h << " px";
    last = t;
  }
  EXPECT_NE(backdrop_light_inputs(f, finest), backdrop_light_inputs(f, 2 * finest)) << "maps of two texels are two maps";
}

TEST(BackdropLight, InputsFollowLightsBackdropAndAimOnly) {
  const FrameState f = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  FrameState tipped = f;
  tipped.vessels[0].pose.orientation = glm::angleAxis(0.3, glm::dvec3(1, 0, 0));
  EXPECT_EQ(backdrop_light_inputs(f), backdrop_light_inputs(tipped)) << "a tipped glass (same placement) changes nothing";
  const FrameState brighter = make_frame(resolve_scene({"lager", "pint", {"light.power=7"}, {}}));
  EXPECT_NE(backdrop_light_inputs(f), backdrop_light_inputs(brighter));
  const FrameState closer = make_frame(resolve_scene({"lager", "pint", {"env.sweep_distance=0.2"}, {}}));
  EXPECT_NE(backdrop_light_inputs(f), backdrop_light_inputs(closer));
}

}  // namespace
}  // namespace draught
