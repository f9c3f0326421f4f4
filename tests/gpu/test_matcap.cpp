// The MatCap tier (render.tier matcap, shaders/passes/matcap.frag.glsl, docs/MATCAP.md):
// - probes: the Thickness debug view (lib/vessel/thickness.glsl view_thickness at the
//   GPU's first surface) against core's view_thickness at the reference intersector's first
//   hit, pixel by pixel: a pint (its wall and thick base), a wine glass (bowl, solid stem,
//   foot), a pint from above (rim, inner wall, the liquid), a flight from an angle.
//   Tolerance: where both see the same surface of the same object away from a change of
//   surface (within a pixel), 99 % of pixels within 0.1 mm + 1 % and none beyond 2 mm +
//   10 % (lines along a wall near the silhouette are ill-conditioned in float);
// - the picture: finite, the glass seen, the drink's colour in it; a still frame bakes and
//   uploads its MatCap once; the MatCap follows the surroundings; droplets and a hot gob
//   are drawn (lenses, the gob glowing), only where they are; so are beads and fog;
// - the background kept once per held view (smaller while the view moves), kept while
//   droplets move; no light map (the floor's, the backdrop's) computed for the tier.
#include "core/scene/camera.hpp"
#include "core/vessel/view_thickness.hpp"
#include "gpu/matcap_texture.hpp"
#include "gpu/scene_data.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

struct ThicknessCase {
  const char* name;
  FrameState (*frame)();
  int size;
};

FrameState pint_front() { return scene_frame({"lager", "pint", {}, {}}); }
FrameState wine() { return scene_frame({"red-wine", "wine", {}, {}}); }
FrameState pint_above() { return scene_frame({"lager", "pint", {}, {"eye=0.08,0.32,0.2", "target=0,0.07,0"}}); }

void PrintTo(const ThicknessCase& c, std::ostream* os) { *os << c.name; }

class MatCapThickness : public ::testing::TestWithParam<ThicknessCase> {};

TEST_P(MatCapThickness, MatchesCoreTwin) {
  const ThicknessCase& c = GetParam();
  const FrameState f = c.frame();
  const int n = c.size;
  const CameraBasis cam = camera_basis(f, n, n);
  const SceneGeometry geo = scene_geometry(f);
  std::vector<Hit> hits(size_t(n) * size_t(n));
  std::vector<double> ref(hits.size(), 0.0);
  auto at = [&](int x, int y) { return size_t(y) * size_t(n) + size_t(x); };
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Ray ray = camera_ray(cam, x + 0.5, y + 0.5, n, n);
      const Hit h = first_hit(geo, ray, 0.0);
      hits[at(x, y)] = h;
      if (h.object < 0) continue;
      const VesselGeometry& g = geo.vessels[size_t(h.object)];
      const glm::dquat to_local = glm::inverse(g.pose.orientation);
      ref[at(x, y)] = view_thickness(*g.vessel, to_local * (ray.at(h.t) - g.pose.position), to_local * ray.d, h.m);
    }
  const gpu::DebugImage img = gpu_instance().renderer->render_debug(f, n, n, gpu::DebugView::Thickness);
  auto on_edge = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Hit& o = hits[at(std::clamp(x + dx, 0, n - 1), std::clamp(y + dy, 0, n - 1))];
        if (o.m != hits[at(x, y)].m || o.object != hits[at(x, y)].object) return true;
      }
    return false;
  };
  int compared = 0, loose = 0, far = 0, glass = 0;
  double worst = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const float* g = img.px(x, y);
      const Hit& h = hits[at(x, y)];
      if (int(std::lround(g[1])) != int(h.m) || int(std::lround(g[2])) != h.object || on_edge(x, y)) continue;
      ++compared;
      const double r = ref[at(x, y)], d = std::abs(double(g[0]) - r);
      glass += r > 0;
      worst = std::max(worst, d);
      loose += d > 1e-4 + 0.01 * r;
      far += d > 2e-3 + 0.1 * r;
    }
  std::printf("[%s] %d pixels compared (%d through glass), %d beyond 0.1 mm + 1 %%, %d beyond 2 mm + 10 %%, worst %.3g mm\n",
              c.name, compared, glass, loose, far, worst * 1e3);
  EXPECT_GT(glass, n * n / 20);  // the glass is in the picture
  EXPECT_LE(loose, compared / 100);
  EXPECT_EQ(far, 0);
}

INSTANTIATE_TEST_SUITE_P(Views, MatCapThickness,
                         ::testing::Values(ThicknessCase{"pint_front", pint_front, 96},
                                           ThicknessCase{"wine", wine, 96},
                                           ThicknessCase{"pint_above", pint_above, 96},
                                           ThicknessCase{"flight_angle", flight_angle, 128}),
                         [](const auto& info) { return std::string(info.param.name); });

FrameState matcap_tier(FrameState f) {
  f.params.render.tier = int(RenderTier::MatCap);
  return f;
}

TEST(MatCapTier, DrawsTheGlassAndItsDrink) {
  Gpu& g = gpu_instance();
  const FrameState f = matcap_tier(pint_front());
  const Image img = g.renderer->render(f, 96, 96);
  // The middle of the glass is the lager's gold (red over blue), the corner the backdrop's grey.
  const std::uint8_t* mid = img.px(48, 50);
  const std::uint8_t* corner = img.px(4, 4);
  EXPECT_GT(int(mid[0]) - int(mid[2]), 40);
  EXPECT_LT(std::abs(int(corner[0]) - int(corner[2])), 12);
  // And it is another picture than the full tier's.
  const Image full = g.renderer->render(pint_front(), 96, 96);
  long differ = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) differ += std::abs(int(img.rgba[i]) - int(full.rgba[i])) > 8;
  EXPECT_GT(differ, 96 * 96 / 50);
}

// The head is lit on the key light's side, round like the full tier's, not one flat tone:
// its pixels (those that a black head darkens) are brighter on the key's third than on the other
// third by more than a tenth of the scale, and the other way round with the key mirrored.
TEST(MatCapTier, TheHeadIsLitOnTheKeysSide) {
  Gpu& g = gpu_instance();
  const int n = 128;
  auto picture = [&](const char* key, const char* colour) {
    return g.renderer->render(scene_frame({"lager", "pint", {"render.tier=matcap", key, colour}, {}}), n, n);
  };
  for (const bool key_left : {true, false}) {
    const char* key = key_left ? "light.direction=-0.6,0.6,0.55" : "light.direction=0.6,0.6,0.55";
    const Image with = picture(key, "foam.color=0.92,0.9,0.85"), without = picture(key, "foam.color=0,0,0");
    int lo = n, hi = -1;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (std::abs(int(with.px(x, y)[1]) - int(without.px(x, y)[1])) > 24) lo = std::min(lo, x), hi = std::max(hi, x);
    ASSERT_GT(hi - lo, n / 4) << "no head in the picture";
    const int third = (hi - lo + 1) / 3;
    double left = 0, right = 0;
    int nl = 0, nr = 0;
    for (int y = 0; y < n; ++y)
      for (int x = lo; x <= hi; ++x) {
        if (std::abs(int(with.px(x, y)[1]) - int(without.px(x, y)[1])) <= 24) continue;
        if (x < lo + third) left += with.px(x, y)[1], ++nl;
        if (x > hi - third) right += with.px(x, y)[1], ++nr;
      }
    ASSERT_GT(nl, 10);
    ASSERT_GT(nr, 10);
    left /= nl;
    right /= nr;
    std::printf("key on the %s: the head's left third %.1f, right third %.1f\n", key_left ? "left" : "right", left, right);
    EXPECT_GT(key_left ? left - right : right - left, 25.5);
  }
}

// A hazy drink has the full tier's colour: the haze dims what lies behind and its light is
// coloured by the drink along the line (before, the MatCap hefeweizen was a pale yellow,
// 50-75 levels off in green and blue).
TEST(MatCapTier, AHazyDrinkHasTheFullTiersColour) {
  Gpu& g = gpu_instance();
  const int n = 128;
  const FrameState full = scene_frame({"hefeweizen", "weizen", {}, {}});
  const Image a = g.renderer->render(full, n, n), b = g.renderer->render(matcap_tier(full), n, n);
  // A patch in the middle of the drink, below the head (the glass's axis, 45 % down).
  for (int c = 0; c < 3; ++c) {
    double sa = 0, sb = 0;
    for (int y = -3; y <= 3; ++y)
      for (int x = -3; x <= 3; ++x) sa += a.px(n / 2 + x, n * 45 / 100 + y)[c], sb += b.px(n / 2 + x, n * 45 / 100 + y)[c];
    std::printf("channel %d: full tier %.1f, MatCap %.1f\n", c, sa / 49, sb / 49);
    EXPECT_NEAR(sb / 49, sa / 49, 20.0) << "channel " << c;
  }
}

// The droplets and the point clouds are in the tier's picture: droplets-seed with and
// without its droplets differs only inside the droplets' box on the screen, and there on
// a droplet's worth of pixels; the molten gob glows (orange: red well over blue).
TEST(MatCapTier, DrawsDropletsAndPointClouds) {
  Gpu& g = gpu_instance();
  SceneRequest req;
  req.preset = "droplets-seed";
  const FrameState with = matcap_tier(make_frame(resolve_scene_objects(req)));
  FrameState without = with;
  without.droplets.clear();
  constexpr int kW = 160, kH = 120;
  const Image a = g.renderer->render(with, kW, kH), b = g.renderer->render(without, kW, kH);
  // The droplets' box (their spheres grown by the blend) on the screen.
  const CameraBasis cam = camera_basis(with.camera_for(kW, kH), kW, kH);
  auto project_to_pixels = [&](const glm::vec3& p) {  // (camera_ray's inverse; the lens not shifted)
    const glm::vec3 q = p - cam.eye;
    const float z = glm::dot(q, cam.forward);
    const float x = glm::dot(q, cam.right) / z / (cam.aspect * cam.tan_half_vfov), y = glm::dot(q, cam.up) / z / cam.tan_half_vfov;
    return glm::vec2((x + 1.0f) * 0.5f * float(kW), (1.0f - y) * 0.5f * float(kH));
  };
  glm::vec2 lo(1e9f), hi(-1e9f);
  const DropletField& field = with.droplets.front().field;
  for (const DropletSphere& s : field.spheres)
    for (int corner = 0; corner < 8; ++corner) {
      const float r = float(s.radius + field.blend + field.noise_amplitude);
      const glm::vec3 p = glm::vec3(s.centre) + r * glm::vec3(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
      const glm::vec2 px = project_to_pixels(p);
      lo = glm::min(lo, px);
      hi = glm::max(hi, px);
    }
  long inside = 0, outside = 0;
  double drop_sum = 0, behind_sum = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::uint8_t *p = a.px(x, y), *q = b.px(x, y);
      const bool differ = std::abs(int(p[0]) - int(q[0])) + std::abs(int(p[1]) - int(q[1])) + std::abs(int(p[2]) - int(q[2])) > 6;
      const bool in = x >= lo.x - 1 && x <= hi.x + 1 && y >= lo.y - 1 && y <= hi.y + 1;
      (in ? inside : outside) += differ;
      if (differ && in) drop_sum += p[0] + p[1] + p[2], behind_sum += q[0] + q[1] + q[2];
    }
  std::printf("droplets: %ld pixels differ inside their box (%.0f x %.0f px), %ld outside; the drop %.0f %% as bright as "
              "what it hides\n",
              inside, hi.x - lo.x, hi.y - lo.y, outside, 100.0 * drop_sum / std::max(behind_sum, 1.0));
  EXPECT_GT(inside, 60);
  EXPECT_EQ(outside, 0);
  // Clear water in a white studio is about as bright as the paper it hides (a MatCap baked
  // from the floor under the droplets showed them dark, as chrome).
  EXPECT_GT(drop_sum, 0.7 * behind_sum);

  req.preset = "molten-gob";
  const Image gob = g.renderer->render(matcap_tier(make_frame(resolve_scene_objects(req))), kW, kH);
  long glowing = 0;
  for (std::size_t i = 0; i < gob.rgba.size(); i += 4) glowing += gob.rgba[i] > 200 && int(gob.rgba[i]) - int(gob.rgba[i + 2]) > 120;
  EXPECT_GT(glowing, kW * kH / 20);
}

// Condensation in the tier: the cold lager's beads and fog change the glass (a good part of
// it), nothing beyond the glass, and the beads make it vary from pixel to pixel.
TEST(MatCapTier, DrawsCondensation) {
  Gpu& g = gpu_instance();
  SceneRequest req;
  req.preset = "cold-lager";
  // (Adaptive supersampling off: it smooths the beads' pixels, which the roughness counts.)
  req.sets = {"render.adaptive_supersample=1"};
  const FrameState cold = matcap_tier(make_frame(resolve_scene_objects(req)));
  ASSERT_TRUE(cold.vessels.at(0).condensation);
  FrameState dry = cold;
  dry.vessels[0].condensation = nullptr;
  constexpr int kS = 128;
  const Image a = g.renderer->render(cold, kS, kS), b = g.renderer->render(dry, kS, kS);
  long differ = 0, beyond = 0;
  double rough_cold = 0, rough_dry = 0;  // the mean step between neighbours across the glass's middle
  for (int y = 0; y < kS; ++y)
    for (int x = 0; x < kS; ++x) {
      const std::uint8_t *p = a.px(x, y), *q = b.px(x, y);
      const int d = std::abs(int(p[0]) - int(q[0])) + std::abs(int(p[1]) - int(q[1])) + std::abs(int(p[2]) - int(q[2]));
      const bool glass_columns = x > kS / 4 && x < 3 * kS / 4;
      differ += d > 6;
      beyond += d > 6 && !glass_columns;
      if (glass_columns && y > kS / 3 && y < 2 * kS / 3 && x + 1 < kS) {
        rough_cold += std::abs(int(p[1]) - int(a.px(x + 1, y)[1]));
        rough_dry += std::abs(int(q[1]) - int(b.px(x + 1, y)[1]));
      }
    }
  std::printf("condensation: %ld pixels differ (%ld outside the glass's columns); neighbour steps %.0f cold, %.0f dry\n",
              differ, beyond, rough_cold, rough_dry);
  EXPECT_GT(differ, kS * kS / 10);
  EXPECT_EQ(beyond, 0);
  EXPECT_GT(rough_cold, 2.0 * rough_dry);
}

TEST(MatCapTier, AStillFrameBakesAndUploadsOnce) {
  Gpu& g = gpu_instance();
  FrameState f = matcap_tier(pint_front());
  f.params.env.sky_top = {0.031f, 0.02f, 0.02f};  // surroundings no other test bakes
  g.renderer->render(f, 32, 32);
  const int uploads = g.renderer->matcap_texture().uploads();
  g.renderer->render(f, 32, 32);
  EXPECT_EQ(g.renderer->matcap_texture().uploads(), uploads);
  f.params.light.power *= 2;  // the surroundings change: a new bake
  g.renderer->render(f, 32, 32);
  EXPECT_EQ(g.renderer->matcap_texture().uploads(), uploads + 1);
}

TEST(MatCapTier, TheBackgroundIsKeptOncePerHeldViewAndDrawnSmallerWhileMoving) {
  Gpu& g = gpu_instance();
  FrameState f = matcap_tier(pint_front());
  f.camera.eye.y += 0.003f;  // a view no other test draws
  gpu::RenderTarget target(48, 48, gpu::RenderTarget::Format::Rgba8);
  const int before = g.renderer->matcap_background().draws();
  g.renderer->draw(f, 48, 48);  // seen once: inline
  EXPECT_EQ(g.renderer->matcap_background().draws(), before);
  g.renderer->draw(f, 48, 48);  // held for a frame: kept
  EXPECT_EQ(g.renderer->matcap_background().draws(), before + 1);
  g.renderer->draw(f, 48, 48);
  g.renderer->draw(f, 48, 48);
  EXPECT_EQ(g.renderer->matcap_background().draws(), before + 1);
  // (render draws at its own supersampled size: a view seen once, then held.)
  const Image inline_picture = g.renderer->render(f, 48, 48);
  const Image kept_picture = g.renderer->render(f, 48, 48);
  EXPECT_EQ(g.renderer->matcap_background().draws(), before + 2);
  int worst = 0;
  for (size_t i = 0; i < inline_picture.rgba.size(); ++i)
    worst = std::max(worst, std::abs(int(inline_picture.rgba[i]) - int(kept_picture.rgba[i])));
  EXPECT_LE(worst, 1) << "inline and kept backgrounds are the same picture (half floats kept)";
  // A camera that moves every frame: a new view each frame, none kept; from the second
  // new view in a row, in an interactive app's renderer, the background is drawn smaller.
  g.renderer->set_moving_drafts(true);
  FrameState moved = f;
  const int small = g.renderer->matcap_background().small_draws();
  for (int i = 1; i <= 4; ++i) {
    moved.camera.eye.x = f.camera.eye.x + 0.002f * float(i);
    g.renderer->draw(moved, 48, 48);
  }
  EXPECT_EQ(g.renderer->matcap_background().draws(), before + 2);
  EXPECT_EQ(g.renderer->matcap_background().small_draws(), small + 3);
  g.renderer->draw(moved, 48, 48);  // it stops: kept again
  EXPECT_EQ(g.renderer->matcap_background().draws(), before + 3);
  // The smaller background is the same picture, softer: a moving frame against the same
  // view held.
  moved.camera.eye.x += 0.002f;
  g.renderer->render(moved, 48, 48);  // a new view (inline)
  moved.camera.eye.x += 0.002f;
  const Image softer = g.renderer->render(moved, 48, 48);  // a second in a row: smaller
  const Image sharp = g.renderer->render(moved, 48, 48);   // held: kept whole
  double sum = 0;
  for (size_t i = 0; i < softer.rgba.size(); ++i) sum += std::abs(int(softer.rgba[i]) - int(sharp.rgba[i]));
  const double mean = sum / double(softer.rgba.size());
  std::printf("smaller background while moving: mean difference %.3f levels\n", mean);
  EXPECT_GT(g.renderer->matcap_background().small_draws(), small + 3);
  EXPECT_LT(mean, 1.0);
  // The CLI's and the tests' renderer draws every frame's background whole.
  g.renderer->set_moving_drafts(false);
  const int small_now = g.renderer->matcap_background().small_draws();
  for (int i = 0; i < 3; ++i) {
    moved.camera.eye.x += 0.002f;
    g.renderer->draw(moved, 48, 48);
  }
  EXPECT_EQ(g.renderer->matcap_background().small_draws(), small_now);
}

// Droplets following a pointer change nothing behind them in the tier (its backdrop has
// no traced shadows): the background kept for the view serves each frame as they move, not
// drawn again (nor smaller, as for a moving camera), and it is the picture drawn with its
// background inline.
TEST(MatCapTier, MovingDropletsKeepTheBackground) {
  Gpu& g = gpu_instance();
  SceneRequest req;
  req.preset = "droplets-seed";
  FrameState f = matcap_tier(make_frame(resolve_scene_objects(req)));
  f.camera.eye.y += 0.004f;  // a view no other test draws
  ASSERT_FALSE(f.droplets.empty());
  g.renderer->set_moving_drafts(true);
  const int before = g.renderer->matcap_background().draws();
  for (int i = 0; i < 3; ++i) g.renderer->draw(f, 48, 48);  // held: kept (the backdrop's light settles after a frame)
  ASSERT_GT(g.renderer->matcap_background().draws(), before);
  const int draws = g.renderer->matcap_background().draws(), small = g.renderer->matcap_background().small_draws();
  FrameState moved = f;
  for (int i = 1; i <= 4; ++i) {
    for (DropletSphere& s : moved.droplets.front().field.spheres) s.centre.x += 0.004;
    g.renderer->draw(moved, 48, 48);
  }
  g.renderer->set_moving_drafts(false);
  EXPECT_EQ(g.renderer->matcap_background().draws(), draws);
  EXPECT_EQ(g.renderer->matcap_background().small_draws(), small);
  // (render draws at its own supersampled size: the kept background of f's view, then the
  // moved droplets over it; against them over a background drawn inline, after another view.)
  g.renderer->render(f, 48, 48);
  g.renderer->render(f, 48, 48);
  const Image kept = g.renderer->render(moved, 48, 48);
  FrameState other = moved;
  other.camera.eye.x += 0.003f;
  g.renderer->render(other, 48, 48);
  const Image inline_picture = g.renderer->render(moved, 48, 48);
  int worst = 0;
  long differ = 0;
  for (size_t i = 0; i < kept.rgba.size(); ++i) {
    const int d = std::abs(int(kept.rgba[i]) - int(inline_picture.rgba[i]));
    worst = std::max(worst, d);
    differ += d > 0;
  }
  std::printf("moved droplets over the kept background against inline: worst %d levels, %ld values differ\n", worst, differ);
  EXPECT_LE(worst, 1);
}

// The tier reads no light map (its backdrop has no traced shadows and takes the rig's
// light per pixel): a frame whose droplets moved traces no floor light, one whose light
// changed computes no backdrop light, and the block says there are none; the full tier's
// next frame computes both.
TEST(MatCapTier, ComputesNoLightMaps) {
  Gpu& g = gpu_instance();
  SceneRequest req;
  req.preset = "droplets-seed";
  FrameState f = matcap_tier(make_frame(resolve_scene_objects(req)));
  ASSERT_FALSE(f.droplets.empty());
  ASSERT_FALSE(f.lights.lights.empty());
  for (int i = 1; i <= 3; ++i) {
    for (DropletSphere& s : f.droplets.front().field.spheres) s.centre.y += 0.003;
    f.lights.lights.front().radiance *= 1.01;
    g.renderer->draw(f, 32, 32);
    EXPECT_FALSE(g.renderer->scene_textures().floor_light_computed()) << "frame " << i;
    EXPECT_FALSE(g.renderer->scene_textures().backdrop_light_computed()) << "frame " << i;
    contract::FrameBlock b{};
    b.floor_light_on = b.backdrop_light_on = 1;
    g.renderer->scene_textures().describe_floor_light(b);
    g.renderer->scene_textures().describe_backdrop_light(b);
    EXPECT_EQ(b.floor_light_on, 0);
    EXPECT_EQ(b.backdrop_light_on, 0);
  }
  f.params.render.tier = int(RenderTier::Full);
  g.renderer->draw(f, 32, 32);
  EXPECT_TRUE(g.renderer->scene_textures().floor_light_computed()) << "the full tier's frame traces its floor's light";
  EXPECT_TRUE(g.renderer->scene_textures().backdrop_light_computed()) << "the full tier's frame computes its backdrop's light";
}

// Every matcap.* number at its minimum and its maximum: a picture with no black hole (a NaN
// shows as black). (matcap.tint black is a black glass body, rightly.)
TEST(MatCapTier, ExtremeParametersDrawAPicture) {
  Gpu& g = gpu_instance();
  for (const ParamDesc& d : param_table()) {
    if (!d.path.starts_with("matcap.") || d.type != ParamType::Float) continue;
    for (float v : {d.min, d.max}) {
      FrameState f = matcap_tier(pint_front());
      set_param(f.params, d, ParamValue(v));
      const Image img = g.renderer->render(f, 48, 48);
      long black = 0;
      for (size_t i = 0; i < img.rgba.size(); i += 4) black += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2] == 0;
      EXPECT_EQ(black, 0) << d.path << " = " << v;
    }
  }
}

}  // namespace
}  // namespace draught::test
