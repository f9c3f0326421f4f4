// The backdrop's light map on the GPU against core: the GLSL twin of backdrop_coords and
// the light the picture takes (the map's texel, or the exact sum where the map does not
// reach or distrusts itself) read out through the BackdropLight debug view, ray by ray
// against core; the picture of the studio's sweep under the whole rig within one 8-bit step
// of the exact analytic shading after the tone map; the map computed once per change of the
// lights or the backdrop, never for an unchanged frame.
#include "core/environment/backdrop_light.hpp"
#include "core/output/tonemap.hpp"
#include "core/scene/camera.hpp"
#include "gpu/scene_data.hpp"
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace draught::test {
namespace {

constexpr int kBackdropW = 96, kBackdropH = 72;

// The default packshot studio around a pint (or `sets` on it), seen through `camera`, the
// glass moved far out of sight after the studio was placed around it.
FrameState sweep_frame(std::vector<std::string> sets, std::vector<std::string> camera) {
  sets.insert(sets.end(), {"bubbles.max_bubbles=0", "render.supersample=1", "camera.auto_frame=false"});
  FrameState f = scene_frame({"lager", "pint", sets, camera});
  for (VesselFrame& v : f.vessels) v.pose.position.x += 50.0;
  return f;
}

// Views of the sweep's floor, curve and wall near the glass (where the strips stand through
// the paper), from afar (partly beyond the map), and the checker floor.
const std::vector<std::vector<std::string>> kViews = {{"eye=0.05,0.2,0.6", "target=0,0.1,-0.3", "vfov=110"},
                                                      {"eye=0.3,0.5,0.4", "target=0,0.2,-0.6", "vfov=80"},
                                                      {"eye=0.0,1.5,3.0", "target=0,0.2,-0.6", "vfov=80"}};

TEST(BackdropLightTwins, CoordsAndLightAgreeWithCore) {
  Gpu& g = gpu_instance();
  int compared = 0, off = 0;
  double worst_xs = 0;
  for (int checker = 0; checker < 2; ++checker)
    for (const auto& camera : kViews) {
      const FrameState f = sweep_frame(checker ? std::vector<std::string>{"env.backdrop=checker"} : std::vector<std::string>{}, camera);
      const gpu::DebugImage d = g.renderer->render_debug(f, kBackdropW, kBackdropH, gpu::DebugView::BackdropLight);
      const CameraBasis cam = camera_basis(f, kBackdropW, kBackdropH);
      for (int y = 0; y < kBackdropH; ++y)
        for (int x = 0; x < kBackdropW; ++x) {
          const Ray r = camera_ray(cam, x + 0.5, y + 0.5, kBackdropW, kBackdropH);
          double t;
          glm::dvec3 n;
          if (!f.backdrop.intersect(r.o, r.d, 0.0, t, n) || d.px(x, y)[3] < 0.5) continue;
          const glm::dvec3 p = r.at(t);
          const glm::dvec2 xs = backdrop_coords(f.backdrop, p);
          worst_xs = std::max(worst_xs, glm::length(xs - glm::dvec2(d.px(x, y)[0], d.px(x, y)[1])) / std::max(1.0, t));
          const double exact = f.lights.irradiance(p, n).g, got = d.px(x, y)[2];
          ++compared;
          // The map's filtering (0.4 %) and half floats (0.05 %); a pixel within float
          // rounding of a light's edge through the paper may see the other side of it.
          off += std::abs(got - exact) > 0.006 * exact + 1e-4;
        }
    }
  std::printf("backdrop light twins: %d pixels, largest |(x, s) GPU - core| %.2e m per m of distance, %d off by > 0.6 %%\n",
              compared, worst_xs, off);
  ASSERT_GT(compared, 20000);
  EXPECT_LT(worst_xs, 1e-5);
  EXPECT_LE(off, compared / 2000);
}

// The picture of the sweep lit by the whole rig, no sky: each pixel within one 8-bit step
// of the exact analytic shading (albedo / pi x the rig's exact irradiance and the paper's
// own bounce, the surround's harmonics: core surround_irradiance; the tone map), lights
// and their neighbours left out.
TEST(BackdropLightPicture, TheSweepIsWithinOneStepOfTheExactShading) {
  Gpu& g = gpu_instance();
  int compared = 0;
  double worst = 0;
  for (const auto& camera : kViews) {
    const FrameState f = sweep_frame({"env.sky_top=0,0,0", "env.sky_horizon=0,0,0", "env.ground=0,0,0"}, camera);
    const Image img = g.renderer->render(f, kBackdropW, kBackdropH);
    const CameraBasis cam = camera_basis(f, kBackdropW, kBackdropH);
    const RenderParams& rp = f.params.render;
    for (int y = 1; y + 1 < kBackdropH; ++y)
      for (int x = 1; x + 1 < kBackdropW; ++x) {
        bool clear = true;  // no light in the pixel or beside it
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const Ray r = camera_ray(cam, x + dx + 0.5, y + dy + 0.5, kBackdropW, kBackdropH);
            for (const AreaLight& l : f.lights.lights) {
              double t;
              clear = clear && !l.intersect(r.o, r.d, 0.0, t);
            }
          }
        const Ray r = camera_ray(cam, x + 0.5, y + 0.5, kBackdropW, kBackdropH);
        double t;
        glm::dvec3 n;
        if (!clear || !f.backdrop.intersect(r.o, r.d, 0.0, t, n)) continue;
        const glm::dvec3 p = r.at(t);
        const glm::dvec3 e =
            f.backdrop.albedo(p) / std::numbers::pi * (f.lights.irradiance(p, n) + f.environment.paper_bounce->at(f.backdrop, p));
        for (int c = 0; c < 3; ++c) {
          double v = e[c] * rp.exposure;
          if (rp.tonemap == int(Tonemap::Aces)) v = aces_filmic(v);
          const double expected = 255.0 * linear_to_srgb(v);  // before rounding
          worst = std::max(worst, std::abs(double(img.px(x, y)[c]) - expected));
          ++compared;
        }
      }
  }
  std::printf("sweep under the rig: %d channels, largest |picture - exact| %.2f 8-bit steps\n", compared, worst);
  ASSERT_GT(compared, 30000);
  // Rounding to 8 bits takes up to half a step; the map up to about 0.3 more.
  EXPECT_LE(worst, 1.0);
}

TEST(BackdropLightPicture, TheMapIsComputedOnlyWhenTheLightsOrTheBackdropChange) {
  Gpu& g = gpu_instance();
  const FrameState f = sweep_frame({"light.power=5.5"}, kViews[0]);
  g.renderer->render(f, kBackdropW, kBackdropH);
  EXPECT_TRUE(g.renderer->scene_textures().backdrop_light_computed());
  ASSERT_FALSE(g.renderer->scene_textures().backdrop_light().empty());
  g.renderer->render(f, kBackdropW, kBackdropH);
  EXPECT_FALSE(g.renderer->scene_textures().backdrop_light_computed()) << "an unchanged frame computed the map again";
  FrameState tipped = f;
  tipped.vessels[0].pose.orientation = glm::angleAxis(0.2, glm::dvec3(1, 0, 0));
  g.renderer->render(tipped, kBackdropW, kBackdropH);
  EXPECT_FALSE(g.renderer->scene_textures().backdrop_light_computed()) << "a tipped glass moves no light";
  g.renderer->render(sweep_frame({"light.power=5.4"}, kViews[0]), kBackdropW, kBackdropH);
  EXPECT_TRUE(g.renderer->scene_textures().backdrop_light_computed()) << "a dimmer key kept the old map";
  g.renderer->render(sweep_frame({"light.power=5.4", "env.sweep_radius=0.25"}, kViews[0]), kBackdropW, kBackdropH);
  EXPECT_TRUE(g.renderer->scene_textures().backdrop_light_computed()) << "another sweep kept the old map";
}

// Interactive apps (Renderer::set_moving_drafts): a frame whose lights just changed gets a
// draft map on texels four times as wide, the next still frame the picture's own.
TEST(BackdropLightPicture, DraftsWhileTheLightsChangeThenThePicturesOwnMap) {
  gpu_instance();  // the GL context the textures are made in
  const int w = 1024, h = 1024;  // (the view is wide: its pixels at the aim are 1.7 mm)
  const FrameState a = sweep_frame({"light.power=5.3"}, kViews[0]), b = sweep_frame({"light.power=5.2"}, kViews[0]);
  gpu::SceneTextures textures;
  textures.set_backdrop_drafts(true);
  textures.update(a, w, h);
  ASSERT_TRUE(textures.backdrop_light_computed());
  const int draft = textures.backdrop_light().width;
  textures.update(a, w, h);
  ASSERT_TRUE(textures.backdrop_light_computed()) << "a still frame after the draft computes the picture's own map";
  const int own = textures.backdrop_light().width;
  EXPECT_EQ(own, compute_backdrop_light(a).width);  // 5 mm
  EXPECT_NEAR(double(own) / draft, 4.0, 0.1);
  textures.update(a, w, h);
  EXPECT_FALSE(textures.backdrop_light_computed());
  textures.update(b, w, h);  // the key's slider moved
  EXPECT_TRUE(textures.backdrop_light_computed());
  EXPECT_EQ(textures.backdrop_light().width, draft);
  textures.update(a, w, h);  // and back: the own map kept for a is taken at once
  EXPECT_FALSE(textures.backdrop_light_computed());
  EXPECT_EQ(textures.backdrop_light().width, own);

  gpu::SceneTextures still;  // drafts off (the CLI): the own map at once
  still.update(b, w, h);
  EXPECT_TRUE(still.backdrop_light_computed());
  EXPECT_EQ(still.backdrop_light().width, own);
}

}  // namespace
}  // namespace draught::test
