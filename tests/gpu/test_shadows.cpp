// The floor's shadows follow the cross-section (clip.*): a glass cut away entirely leaves
// the floor as it is without the glass; a half-cut glass darkens it less than a whole one.
// The floor under a glass shows core's traced light map.
#include "gpu_fixture.hpp"
#include "core/output/tonemap.hpp"
#include "gpu/scene_data.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace draught::test {
namespace {

constexpr int kShadowW = 128, kShadowH = 96;

// A lager in a pint on the checker floor (presets/scenes/checker-studio.json) seen from
// above and in front by a fixed camera, with these extra settings (the cross-section).
// `out_of_sight`: the same studio (its lights stand around the glass) with the glass
// moved far away after the lights were placed.
FrameState glass_on_floor(std::vector<std::string> sets = {}, bool out_of_sight = false) {
  sets.insert(sets.end(), {"bubbles.max_bubbles=0", "render.supersample=1", "camera.auto_frame=false"});
  const Params p = resolve_scene({"checker-studio", "pint", sets, {"eye=0,0.32,0.3", "target=0,0.03,0", "vfov=40"}});
  Scene s;
  s.params = p;
  s.objects.push_back(SceneObject{"glass", Placement{{0.0f, 0.0f, 0.0f}, 0.0f}, VesselObject{p}});
  FrameState f = make_frame(s);
  if (out_of_sight) f.vessels[0].pose.position.x += 20.0;
  return f;
}

// How the floor is darker in `img` than in `bare` (the same floor without the glass):
// over the pixels where the first surface is the floor in `f`, the sum of the
// darkening (0..255 per pixel, mean of the channels) and the count of pixels darkened by
// more than 3.
struct Darkening {
  double sum = 0;
  int pixels = 0;
};
Darkening floor_darkening(const FrameState& f, const Image& bare) {
  Gpu& g = gpu_instance();
  const Image img = g.renderer->render(f, kShadowW, kShadowH);
  const gpu::DebugImage first = g.renderer->render_debug(f, kShadowW, kShadowH, gpu::DebugView::Depth);
  Darkening d;
  for (int y = 0; y < kShadowH; ++y)
    for (int x = 0; x < kShadowW; ++x) {
      if (int(first.px(x, y)[1]) != int(Material::Floor)) continue;
      double dark = 0;
      for (int c = 0; c < 3; ++c) dark += (double(bare.px(x, y)[c]) - double(img.px(x, y)[c])) / 3;
      d.sum += std::max(dark, 0.0);
      d.pixels += dark > 3;
    }
  return d;
}

TEST(Shadows, AGlassCutAwayEntirelyCastsNoShadow) {
  Gpu& g = gpu_instance();
  // The same floor without the glass: the glass stands far out of sight.
  const Image bare = g.renderer->render(glass_on_floor({}, true), kShadowW, kShadowH);
  const Darkening whole = floor_darkening(glass_on_floor(), bare);
  // The cut's normal points up and it lies below the floor: everything is cut away.
  const Darkening cut = floor_darkening(glass_on_floor({"clip.enabled=true", "clip.normal=0,1,0", "clip.offset=-0.05"}), bare);
  const Darkening half = floor_darkening(glass_on_floor({"clip.enabled=true", "clip.normal=1,0,0", "clip.offset=0"}), bare);
  std::printf("floor darkening (sum, pixels): whole glass %.0f, %d; half cut %.0f, %d; cut away %.0f, %d\n", whole.sum,
              whole.pixels, half.sum, half.pixels, cut.sum, cut.pixels);
  ASSERT_GT(whole.pixels, 100) << "the whole glass must shadow the floor in this view (else the test tests nothing)";
  EXPECT_EQ(cut.pixels, 0) << "a glass cut away entirely still darkens the floor";
  EXPECT_LT(cut.sum, 0.01 * whole.sum);
  EXPECT_LT(half.sum, 0.8 * whole.sum) << "half the glass shadows as much as all of it";
  EXPECT_GT(half.sum, 0.1 * whole.sum) << "half the glass casts (almost) no shadow";
}

// Calls visit(x, y, p) for each pixel of a kShadowW x kShadowH picture of f whose first surface is the
// floor at p inside map's rect, short of the texels where it blends into the light outside.
template <class Visit>
void for_each_floor_pixel_in(Gpu& g, const FrameState& f, const FloorLightMap& map, const Visit& visit) {
  const gpu::DebugImage first = g.renderer->render_debug(f, kShadowW, kShadowH, gpu::DebugView::Depth);
  const CameraBasis cam = camera_basis(f, kShadowW, kShadowH);
  const glm::dvec2 margin = 4.0 * map.size / glm::dvec2(map.width, map.height);
  for (int y = 0; y < kShadowH; ++y)
    for (int x = 0; x < kShadowW; ++x) {
      if (int(first.px(x, y)[1]) != int(Material::Floor)) continue;
      const glm::dvec3 p = camera_ray(cam, x + 0.5, y + 0.5, kShadowW, kShadowH).at(first.px(x, y)[0]);
      const glm::dvec2 uv(p.x, p.z);
      if (glm::any(glm::lessThan(uv, map.origin + margin)) || glm::any(glm::greaterThan(uv, map.origin + map.size - margin)))
        continue;
      visit(x, y, p);
    }
}

// The floor's direct light is the unoccluded light times the map's factor: from three
// pictures (the map on, off, and the key off)
// the factor at each floor pixel is (on - dark) / (off - dark); it must be core's. (The
// map's surroundings' shadow is left out here: gather_rays 0.)
TEST(Shadows, TheFloorUnderTheGlassShowsTheMap) {
  Gpu& g = gpu_instance();
  const std::vector<std::string> sets{"render.tonemap=none", "render.exposure=0.7", "strips.power=0", "backlight.power=0"};
  const FrameState f = glass_on_floor(sets);
  std::vector<std::string> dark_sets = sets;
  dark_sets.push_back("light.power=0");
  const FrameState dark = glass_on_floor(dark_sets);
  FloorLightSettings lights_only = test_floor_light();
  lights_only.gather_rays = 0;
  g.renderer->set_floor_light(lights_only);
  const Image on = g.renderer->render(f, kShadowW, kShadowH);
  const FloorLightMap map = g.renderer->scene_textures().floor_light();
  ASSERT_FALSE(map.empty());
  const Image no_key = g.renderer->render(dark, kShadowW, kShadowH);
  g.renderer->set_floor_light(test_floor_light(), false);
  const Image off = g.renderer->render(f, kShadowW, kShadowH);
  g.renderer->set_floor_light(test_floor_light());
  auto linear = [](std::uint8_t v) {
    const double c = v / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  double worst = 0;
  int probed = 0, shaded = 0;
  for_each_floor_pixel_in(g, f, map, [&](int x, int y, const glm::dvec3& p) {
    const glm::dvec3 open = unoccluded_floor_irradiance(f.lights, p);
    const glm::dvec3 expect = map.sample(p.x, p.z) / open;
    for (int c = 0; c < 3; ++c) {
      const double key = linear(off.px(x, y)[c]) - linear(no_key.px(x, y)[c]);
      if (key < 0.1 || linear(off.px(x, y)[c]) > 0.9) continue;  // too dark for 8 bits, or near clipping
      const double got = (linear(on.px(x, y)[c]) - linear(no_key.px(x, y)[c])) / key;
      worst = std::max(worst, std::fabs(got - expect[c]));
      ++probed;
      shaded += expect[c] < 0.8;
    }
  });
  std::printf("floor light factor: %d probes (%d in shadow), largest |GPU - core| %.3f\n", probed, shaded, worst);
  ASSERT_GT(shaded, 50) << "the view misses the shadow";
  // 8-bit pictures (a step is about 1 % of the key's part here), the half-float texture,
  // and the texture filtering the factor where core interpolates the light.
  EXPECT_LT(worst, 0.04);
}

// The paper's own bounce is its unoccluded light times the map's surroundings' factor: on
// the studio's paper (matte), the picture with the map less the picture without the
// surroundings' shadow (gather_rays 0) is the bounce's part of the floor times that
// factor less one, the bounce's part being core's (albedo / pi x the paper's bounce:
// the sweep is within an 8-bit step of it, test_backdrop_light); the factor must be core's.
TEST(Shadows, TheFloorRoundTheFootShowsTheSurroundingsShadow) {
  Gpu& g = gpu_instance();
  const double exposure = 2.0;
  const Params p = resolve_scene({"lager", "pint", {"render.tonemap=none", "render.exposure=2", "bubbles.max_bubbles=0",
                                  "render.supersample=1", "camera.auto_frame=false"},
                                 {"eye=0,0.32,0.3", "target=0,0.03,0", "vfov=40"}});
  const FrameState f = make_frame(p);
  const Image on = g.renderer->render(f, kShadowW, kShadowH);
  const FloorLightMap map = g.renderer->scene_textures().floor_light();
  ASSERT_FALSE(map.empty());
  FloorLightSettings lights_only = test_floor_light();
  lights_only.gather_rays = 0;
  g.renderer->set_floor_light(lights_only);
  const Image without = g.renderer->render(f, kShadowW, kShadowH);
  g.renderer->set_floor_light(test_floor_light());
  double worst = 0, darkest = 1, bias = 0, spread = 0;
  int probed = 0, shaded = 0;
  for_each_floor_pixel_in(g, f, map, [&](int x, int y, const glm::dvec3& q) {
    const glm::dvec3 expect = map.surround_sample(q.x, q.z);
    const glm::dvec3 bounce =
        exposure * f.backdrop.albedo(q) / std::numbers::pi * f.environment.paper_bounce->at(f.backdrop, q);
    for (int c = 0; c < 3; ++c) {
      const double open = srgb_to_linear(without.px(x, y)[c] / 255.0);
      if (bounce[c] < 0.12 || open > 0.9) continue;  // too dark for 8 bits, or near clipping
      const double got = 1 + (srgb_to_linear(on.px(x, y)[c] / 255.0) - open) / bounce[c];
      worst = std::max(worst, std::fabs(got - expect[c]));
      bias += got - expect[c];
      spread += std::fabs(got - expect[c]);
      darkest = std::min(darkest, expect[c]);
      ++probed;
      shaded += expect[c] < 0.9;
    }
  });
  ASSERT_GT(shaded, 50) << "the view misses the contact round the foot";
  bias /= probed;
  spread /= probed;
  std::printf("surroundings' shadow: %d probes (%d darker than 0.9, the darkest %.2f), GPU - core: mean %.4f, mean |.| %.4f, "
              "largest %.3f\n", probed, shaded, darkest, bias, spread, worst);
  // The bounce is a fifth of the floor's light: one 8-bit step of either picture is up to
  // 6 % of it, so the largest difference is the pictures' rounding; on average it is
  // none, and a factor off by 0.02 would show in the mean.
  EXPECT_LT(std::fabs(bias), 0.005);
  EXPECT_LT(spread, 0.02);
  EXPECT_LT(worst, 0.15);
}

}  // namespace
}  // namespace draught::test
