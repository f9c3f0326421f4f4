// The floor's shadows follow the cross-section (clip.*): a glass cut away entirely leaves
// the floor as it is without the glass; a half-cut glass darkens it less than a whole one.
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace draught::test {
namespace {

constexpr int kW = 128, kH = 96;

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
  const Image img = g.renderer->render(f, kW, kH);
  const gpu::DebugImage first = g.renderer->render_debug(f, kW, kH, gpu::DebugView::Depth);
  Darkening d;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
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
  const Image bare = g.renderer->render(glass_on_floor({}, true), kW, kH);
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

}  // namespace
}  // namespace draught::test
