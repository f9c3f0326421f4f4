// A head's detail is drawn only where a picture is large enough to hold it (the bubbles
// pressed against the glass fade out where a cell is under a few pixels), and its mean
// must not move with it: a stout's head in a thumbnail and in a 1080p picture is the same
// colour. The close-up's head side, drawn small and four times as large (one sample a
// pixel, no tone map, dimmed so nothing clips), averaged over the same part of the frame
// in linear light.
#include "gpu_fixture.hpp"

#include "core/output/tonemap.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

// The mean linear light of the part [x0, x1) x [y0, y1) of a picture, in 48ths of its size.
std::array<double, 3> mean_light(const Image& img, int x0, int x1, int y0, int y1) {
  const int scale = img.width / 48;
  std::array<double, 3> sum{};
  int n = 0;
  for (int y = y0 * scale; y < y1 * scale; ++y)
    for (int x = x0 * scale; x < x1 * scale; ++x, ++n)
      for (int c = 0; c < 3; ++c) sum[size_t(c)] += srgb_to_linear(img.px(x, y)[c] / 255.0);
  for (double& s : sum) s /= n;
  return sum;
}

TEST(HeadDetail, TheSideKeepsItsMeanAtAnyPictureSize) {
  Gpu& g = gpu_instance();
  FrameState f = make_frame(resolve_scene({"stout", "nonic", {"render.supersample=1", "render.tonemap=none"},
                                           {"eye=0,0.2,0.3", "target=0,0.14,0", "vfov=22"}}));
  f.params.render.exposure *= 0.25f;
  // The band of the head's side below its top and above the drink, inside the glass's
  // walls (in 48ths of the picture; seen at 192 x 192).
  constexpr int kX0 = 13, kX1 = 35, kY0 = 22, kY1 = 25;
  const Image small = g.renderer->render(f, 48, 48);   // cells about a pixel: faded out
  const Image large = g.renderer->render(f, 192, 192);  // cells several pixels wide: drawn
  const std::array<double, 3> a = mean_light(small, kX0, kX1, kY0, kY1);
  const std::array<double, 3> b = mean_light(large, kX0, kX1, kY0, kY1);
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: 48 x 48 %.4f, 192 x 192 %.4f (%.3fx)\n", c, a[size_t(c)], b[size_t(c)],
                b[size_t(c)] / a[size_t(c)]);
    // Seen: 0.999x, 0.999x, 0.995x (as with no network at all); 0.932x, 0.898x and
    // 0.859x while the borders only darkened (the network's mean not divided out).
    EXPECT_NEAR(b[size_t(c)] / a[size_t(c)], 1.0, 0.02) << "channel " << c;
  }
}

}  // namespace
}  // namespace draught::test
