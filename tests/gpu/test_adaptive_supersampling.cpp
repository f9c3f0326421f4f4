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

// How the adaptive picture stands against the 2 x 2 and the 4 x 4 ones.
struct Against {
  int changed = 0, changed_right = 0, neither = 0;  // changed_right: at x >= right
  double changed_off_four = 0, off_two = 0, off_adaptive = 0;
};
Against compare(const Image& two, const Image& four, const Image& adaptive, int right) {
  Against a;
  for (int y = 0; y < two.height; ++y)
    for (int x = 0; x < two.width; ++x) {
      a.off_two += difference(two, four, x, y);
      a.off_adaptive += difference(adaptive, four, x, y);
      if (difference(adaptive, two, x, y) == 0) continue;
      ++a.changed;
      a.changed_right += x >= right;
      const int d = difference(adaptive, four, x, y);
      a.changed_off_four += d;
      // (The march's jitter follows the tile's own pixel coordinates: a few levels.)
      a.neither += d > 6;
    }
  std::printf("%d pixels changed (%d at x >= %d); off the 4 x 4 picture: changed pixels %.2f levels on average, %d "
              "by more than 6; the picture %.3f levels a pixel, the 2 x 2 one %.3f\n",
              a.changed, a.changed_right, right, a.changed_off_four / std::max(a.changed, 1), a.neither,
              a.off_adaptive / (two.width * two.height), a.off_two / (two.width * two.height));
  return a;
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
  std::printf("%ld pixels refined in %.0f ms\n", refined.pixels, refined.ms);
  EXPECT_EQ(refined.samples, 4);
  EXPECT_GT(refined.pixels, kWidth * kHeight / 100);
  EXPECT_LT(refined.pixels, kWidth * kHeight / 2);  // (a detailed view: 25 % seen)
  const Against a = compare(two, four, adaptive, 1536 / 4);
  EXPECT_GT(a.changed, 100);
  EXPECT_GT(a.changed_right, 10);  // beyond the first tile
  EXPECT_LT(a.changed_off_four / a.changed, 1.0);
  EXPECT_LT(a.neither, a.changed / 100 + 1);
  EXPECT_LT(a.off_adaptive, 0.5 * a.off_two);
}

// A transparent picture (premultiplied display samples, for compositing) is refined in its
// display values, its coverage's edges included.
TEST(AdaptiveSupersampling, ATransparentPictureIsRefinedToo) {
  Gpu& g = gpu_instance();
  auto with = [](std::vector<std::string> sets) {
    sets.insert(sets.end(), {"render.transparent=true", "bubbles.max_bubbles=0"});
    return make_frame(resolve_scene({"lager", "pint", sets, {}}));
  };
  constexpr int kSize = 160;
  const Image two = g.renderer->render(with({"render.adaptive_supersample=1"}), kSize, kSize);
  const Image four = g.renderer->render(with({"render.supersample=4"}), kSize, kSize);
  const Image adaptive = g.renderer->render(with({}), kSize, kSize);
  EXPECT_GT(g.renderer->last_refined().pixels, 0);
  const Against a = compare(two, four, adaptive, kSize);
  int alpha_off_two = 0, alpha_off_adaptive = 0;  // coverage against the 4 x 4 picture's
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      alpha_off_two += std::abs(int(two.px(x, y)[3]) - int(four.px(x, y)[3]));
      alpha_off_adaptive += std::abs(int(adaptive.px(x, y)[3]) - int(four.px(x, y)[3]));
    }
  std::printf("coverage off the 4 x 4 picture's: %d levels in all, %d at 2 x 2\n", alpha_off_adaptive, alpha_off_two);
  EXPECT_GT(a.changed, 100);
  EXPECT_LT(a.changed_off_four / a.changed, 1.5);
  EXPECT_LT(a.neither, a.changed / 50 + 1);
  EXPECT_LT(a.off_adaptive, 0.5 * a.off_two);
  EXPECT_LT(alpha_off_adaptive, alpha_off_two / 2);
}

}  // namespace
}  // namespace draught::test
