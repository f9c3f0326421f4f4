// Bubble sprites: each sits on the pixel whose refracted path really passes through its
// bubble, checked by tracing that pixel's path independently here.
#include "core/bubbles/bubble_view.hpp"
#include "core/scene/camera.hpp"
#include "core/reference/optics.hpp"
#include "core/params/preset.hpp"
#include "core/sim/simulation.hpp"

#include <gtest/gtest.h>

namespace draught {
namespace {

FrameState settled(const SceneRequest& req) {
  const Params p = resolve_scene(req);
  Simulation sim(p);
  sim.settle_bubbles(3.0);
  return assemble_frame(p, {sim.frame()});
}

// Closest distance from world point c to the path of pixel (px, py) once it is in the
// liquid (air -> glass -> liquid through the wall; refraction at each interface).
double path_miss(const FrameState& f, double px, double py, int w, int h, const glm::dvec3& c) {
  const SceneGeometry geo = scene_geometry(f);
  Ray r = camera_ray(camera_basis(f, w, h), px, py, w, h);
  const double n[3] = {1.0, f.vessels[0].params.glass.ior, f.vessels[0].params.liquid.ior};
  int medium = 0;  // air, glass, liquid; through a side wall only
  for (int e = 0; e < 4 && medium != 2; ++e) {
    const Hit hit = first_hit(geo, r, 1e-6);
    if (!hit.valid()) return 1e9;
    const int next = medium == 0 ? 1 : (hit.m == Material::GlassInner ? 2 : 0);
    const glm::dvec3 nn = glm::dot(hit.n, r.d) < 0 ? hit.n : -hit.n;
    const auto d = refract_dir(r.d, nn, n[medium] / n[next]);
    if (!d) return 1e9;
    r = Ray{r.at(hit.t), glm::normalize(*d)};
    medium = next;
  }
  if (medium != 2) return 1e9;
  const double t = glm::dot(c - r.o, r.d);
  return glm::length(c - r.at(t));
}

TEST(BubbleView, SpritesSitWhereTheRefractedViewMeetsTheBubble) {
  // Side view of a lager, level camera: every bubble is seen through the wall.
  const FrameState f = settled({"lager", "pint", {"foam.height=0"}, {"eye=0,0.07,0.3", "target=0,0.07,0", "vfov=30"}});
  ASSERT_GT(f.vessels[0].bubbles.size(), 50u);
  const int w = 200, h = 200;
  const auto sprites = bubble_sprites(f, w, h);
  ASSERT_GT(sprites.size(), 20u);
  // Match each sprite to the bubble its path passes closest to; within its radius.
  int checked = 0;
  for (const BubbleSprite& s : sprites) {
    double best = 1e9, radius = 0;
    for (const Bubble& b : f.vessels[0].bubbles) {
      const double miss = path_miss(f, s.centre.x, s.centre.y, w, h, glm::dvec3(b.p));
      if (miss < best) best = miss, radius = b.radius;
    }
    if (best > 1e8) continue;  // seen through the floor or the surface: not this test's path
    EXPECT_LT(best, 0.25 * radius) << "sprite at " << s.centre.x << "," << s.centre.y;
    ++checked;
  }
  EXPECT_GT(checked, 20);
  // Drawn back to front, so nearer bubbles cover farther ones.
  for (size_t i = 1; i < sprites.size(); ++i) EXPECT_GE(sprites[i - 1].distance, sprites[i].distance);  // far first
}

// The MatCap tier bends no view: its sprites sit where the camera's straight line meets
// each bubble, sized by the distance, and dimmed by the drink in front of them.
TEST(BubbleView, TheMatCapTiersSpritesSitOnTheStraightView) {
  FrameState f = settled({"lager", "pint", {"foam.height=0", "render.tier=matcap"}, {"eye=0,0.07,0.3", "target=0,0.07,0", "vfov=30"}});
  const int w = 200, h = 200;
  const auto sprites = bubble_sprites(f, w, h);
  ASSERT_GT(sprites.size(), 20u);
  const CameraBasis cam = camera_basis(f, w, h);
  int matched = 0;
  for (const BubbleSprite& s : sprites) {
    // The bubble whose straight line passes nearest the sprite's pixel, within its radius.
    const Ray r = camera_ray(cam, s.centre.x, s.centre.y, w, h);
    double best = 1e9, radius = 0, depth = 0;
    for (const Bubble& b : f.vessels[0].bubbles) {
      const glm::dvec3 c(b.p);
      const double t = glm::dot(c - r.o, r.d), miss = glm::length(c - r.at(t));
      if (miss < best) best = miss, radius = b.radius, depth = glm::dot(c - r.o, glm::dvec3(cam.forward));
    }
    EXPECT_LT(best, 1e-3 * radius + 1e-9) << "sprite at " << s.centre.x << "," << s.centre.y;
    EXPECT_NEAR(s.radius, radius / (2.0 * depth * cam.tan_half_vfov / h), 1e-3 * s.radius);
    EXPECT_LT(s.tint.b, s.tint.r);  // through lager: blue goes first
    matched += best < 1e-3 * radius + 1e-9;
  }
  EXPECT_EQ(matched, int(sprites.size()));
  // Not where the refracted view puts them.
  f.params.render.tier = int(RenderTier::Full);
  const auto bent = bubble_sprites(f, w, h);
  ASSERT_FALSE(bent.empty());
  EXPECT_NE(bent.front().centre, sprites.front().centre);
}

TEST(BubbleView, HiddenUnderTheHeadFromAbove) {
  // Looking straight down into a pint: with a head, no bubble shows; without, many do.
  const std::vector<std::string> above = {"eye=0,0.5,0.001", "target=0,0,0", "vfov=20"};
  const FrameState with_head = settled({"lager", "pint", {"foam.height=0.015"}, above});
  const FrameState no_head = settled({"lager", "pint", {"foam.height=0"}, above});
  EXPECT_TRUE(bubble_sprites(with_head, 128, 128).empty());
  EXPECT_GT(bubble_sprites(no_head, 128, 128).size(), 10u);
}

TEST(BubbleView, StillWineHasNoneAndTintFollowsTheDrink) {
  EXPECT_TRUE(bubble_sprites(settled({"red-wine", "wine", {}, {}}), 128, 128).empty());
  const auto stout = bubble_sprites(settled({"stout", "nonic", {"foam.height=0"}, {}}), 128, 128);
  const auto lager = bubble_sprites(settled({"lager", "nonic", {"foam.height=0"}, {}}), 128, 128);
  ASSERT_FALSE(stout.empty());
  ASSERT_FALSE(lager.empty());
  auto mean_blue = [](const std::vector<BubbleSprite>& v) {
    double s = 0;
    for (auto& x : v) s += x.tint.b;
    return s / double(v.size());
  };
  EXPECT_LT(mean_blue(stout), 0.5 * mean_blue(lager));  // seen through dark beer
}

}  // namespace
}  // namespace draught
