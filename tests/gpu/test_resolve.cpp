// A supersampled picture is resolved in scene-linear light (gpu::Renderer::render,
// core/output/resolve): its samples' light averaged, then tone mapped once, as the
// reference resolves its paths. Checked against a prediction from single samples: the
// same view at twice the size, one sample a pixel, drawn without a tone map at an eighth
// of the exposure (so no sample clips), decoded, averaged 2 x 2 and tone mapped.
#include "gpu_fixture.hpp"

#include "core/output/tonemap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace draught::test {
namespace {

TEST(Resolve, SupersamplesAreAveragedInSceneLinearLight) {
  Gpu& g = gpu_instance();
  // The bar's lamps and bottles seen through a pint's base: bands of bright stripes finer
  // than a pixel, where the order of averaging and tone mapping shows.
  const std::vector<std::string> camera = {"eye=0,0.05,0.3", "target=0,0.02,0", "vfov=20"};
  const std::vector<std::string> base = {"env.mode=image", "env.image=bar", "bubbles.max_bubbles=0",
                                         "camera.auto_frame=false"};
  auto with = [&](std::vector<std::string> sets) {
    sets.insert(sets.begin(), base.begin(), base.end());
    return make_frame(resolve_scene({"lager", "pint", sets, camera}));
  };
  constexpr int kSize = 48;
  // (Adaptive supersampling off: the picture is its 2 x 2 samples' alone.)
  const Image picture = g.renderer->render(with({"render.supersample=2", "render.adaptive_supersample=1"}), kSize, kSize);
  constexpr double kDim = 8.0;
  FrameState dim = with({"render.supersample=1", "render.tonemap=none"});
  const double exposure = dim.params.render.exposure;
  dim.params.render.exposure = float(exposure / kDim);
  const Image samples = g.renderer->render(dim, 2 * kSize, 2 * kSize);
  double linear_error = 0, display_error = 0, worst = 0;
  int n = 0, clipped = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c) {
        // (A lamp's light clips even dimmed: those pixels cannot be predicted.)
        bool clips = false;
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i) clips = clips || samples.px(2 * x + i, 2 * y + j)[c] == 255;
        clipped += clips;
        if (clips) continue;
        ++n;
        double light = 0, shown = 0;  // the samples' mean light; the mean of their tone-mapped light
        for (int j = 0; j < 2; ++j)
          for (int i = 0; i < 2; ++i) {
            const double l = srgb_to_linear(samples.px(2 * x + i, 2 * y + j)[c] / 255.0) * kDim;
            light += 0.25 * l;
            shown += 0.25 * srgb_to_linear(display_code(l, int(Tonemap::Aces)) / 255.0);
          }
        const double got = picture.px(x, y)[c];
        const double e = std::abs(got - display_code(light, int(Tonemap::Aces)));
        linear_error += e;
        worst = std::max(worst, e);
        display_error += std::abs(got - std::lround(linear_to_srgb(shown) * 255.0));
      }
  std::printf("supersampled picture against its samples resolved in scene-linear light: mean %.2f, worst %.0f "
              "levels; against them resolved after the tone map: mean %.2f (%d of %d values left out: clipped)\n",
              linear_error / n, worst, display_error / n, clipped, n + clipped);
  EXPECT_LT(clipped, n / 100);
  // The dimmed samples' 8-bit codes are coarse in the dark (a level there is several in
  // the prediction): 0.48 levels on the mean, 2 at worst, seen; resolved after the tone
  // map the samples are 2.1 levels off on the mean.
  EXPECT_LT(linear_error / n, 0.8);
  EXPECT_LT(worst, 6.0);
  EXPECT_GT(display_error, 3.0 * linear_error);
}

}  // namespace
}  // namespace draught::test
