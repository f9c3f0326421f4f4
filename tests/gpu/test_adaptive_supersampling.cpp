// Adaptive supersampling (gpu::Renderer::render, core/output/refine): the pixels whose
// 2 x 2 samples disagree are drawn again at 4 x 4, in tiles of the four-times-larger
// picture. Each pixel of the picture is then either its 2 x 2 resolve (unchanged) or the
// 4 x 4 picture's pixel, across the tiles' borders too.
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace draught::test {
namespace {

int difference(const Image& a, const Image& b, int x, int y) {
  int d = 0;
  for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.px(x, y)[c]) - int(b.px(x, y)[c])));
  return d;
}

TEST(AdaptiveSupersampling, RefinedPixelsAreTheFinerPicturesAndTheOthersKeepTheirSamples) {
  Gpu& g = gpu_instance();
  // The bar's lamps and bottles through a pint's base and its walls' edges: fine detail.
  auto with = [](std::vector<std::string> sets) {
    sets.insert(sets.end(), {"env.mode=image", "env.image=bar", "bubbles.max_bubbles=0", "camera.auto_frame=false"});
    return make_frame(resolve_scene({"lager", "pint", sets, {"eye=0,0.09,0.32", "target=0,0.06,0", "vfov=30"}}));
  };
  // 400 pixels wide: the 4 x 4 picture is 1600 samples, two of the renderer's tiles (1536).
  constexpr int kWidth = 400, kHeight = 200;
  const Image two = g.renderer->render(with({"render.supersample=2", "render.adaptive_supersample=1"}), kWidth, kHeight);
  EXPECT_EQ(g.renderer->last_refined().pixels, 0);
  const Image four = g.renderer->render(with({"render.supersample=4"}), kWidth, kHeight);
  const Image adaptive = g.renderer->render(with({"render.supersample=2", "render.adaptive_supersample=4"}), kWidth, kHeight);
  const gpu::Renderer::Refined refined = g.renderer->last_refined();
  EXPECT_EQ(refined.samples, 4);
  EXPECT_GT(refined.pixels, kWidth * kHeight / 100);
  EXPECT_LT(refined.pixels, kWidth * kHeight / 2);  // (a detailed view: 25 % seen)
  int changed = 0, changed_beyond_tile = 0, neither = 0;
  double off_two = 0, off_adaptive = 0, changed_off_four = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      off_two += difference(two, four, x, y);
      off_adaptive += difference(adaptive, four, x, y);
      if (difference(adaptive, two, x, y) == 0) continue;
      ++changed;
      changed_beyond_tile += x >= 1536 / 4;
      const int d = difference(adaptive, four, x, y);
      changed_off_four += d;
      // (The march's jitter follows the tile's own pixel coordinates: a few levels.)
      neither += d > 6;
    }
  std::printf("%ld pixels refined (%d changed, %d of them beyond the first tile) in %.0f ms; off the 4 x 4 "
              "picture: changed pixels %.2f levels on average, %d by more than 6; the picture %.3f levels a "
              "pixel, the 2 x 2 one %.3f\n",
              refined.pixels, changed, changed_beyond_tile, refined.ms, changed_off_four / std::max(changed, 1),
              neither, off_adaptive / (kWidth * kHeight), off_two / (kWidth * kHeight));
  EXPECT_GT(changed, 100);
  EXPECT_GT(changed_beyond_tile, 10);
  EXPECT_LT(changed_off_four / changed, 1.0);
  EXPECT_LT(neither, changed / 100 + 1);
  EXPECT_LT(off_adaptive, 0.5 * off_two);
}

}  // namespace
}  // namespace draught::test
