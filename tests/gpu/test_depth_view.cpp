// The depth debug view a person looks at (the viewer's D key, `draught render --debug
// depth`): the glass spreads over the greys of the scene's depth range instead of being
// squeezed into white by the floor running to the horizon.
#include "gpu_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace draught::test {
namespace {

// The grey of every pixel where the GPU's first surface is a glass.
std::vector<int> glass_greys(const gpu::DebugImage& d, const Image& img) {
  std::vector<int> out;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x)
      if (d.px(x, y)[2] >= 0 && d.px(x, y)[0] > 0) out.push_back(img.px(x, y)[0]);
  std::sort(out.begin(), out.end());
  return out;
}

double mean(const std::vector<int>& v) {
  double s = 0;
  for (int g : v) s += g;
  return s / double(v.size());
}

TEST(DepthView, TheGlassSpansTheGreys) {
  Gpu& g = gpu_instance();
  const FrameState f = scene_frame({"lager", "pint", {}, {}});
  const int n = 96;
  const gpu::DebugImage depth = g.renderer->render_debug(f, n, n, gpu::DebugView::Depth);
  const DepthRange range = depth_range(f, n, n);
  // The GPU's distances of the glass lie in the range (a hair of float error allowed).
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      if (depth.px(x, y)[2] >= 0 && depth.px(x, y)[0] > 0) {
        ASSERT_GE(depth.px(x, y)[0], range.near - 1e-4) << x << "," << y;
        ASSERT_LE(depth.px(x, y)[0], range.far + 1e-4) << x << "," << y;
      }
  const std::vector<int> greys = glass_greys(depth, gpu::visualize_debug(depth, gpu::DebugView::Depth, range));
  ASSERT_GT(greys.size(), 500u);
  const int lo = greys[greys.size() / 20], hi = greys[greys.size() * 19 / 20];
  std::printf("glass greys: 5 %% %d, 95 %% %d, mean %.0f\n", lo, hi, mean(greys));
  EXPECT_GE(hi - lo, 60) << "the glass is one grey";
  EXPECT_LT(mean(greys), 225) << "the glass is nearly white";
  // What it was: normalised over the picture's depths, the floor's far end squeezed the
  // glass into the top few greys.
  const std::vector<int> before = glass_greys(depth, gpu::visualize_debug(depth, gpu::DebugView::Depth));
  std::printf("over the picture's depths: glass greys 5 %% %d, 95 %% %d\n", before[before.size() / 20],
              before[before.size() * 19 / 20]);
  EXPECT_LT(before[before.size() * 19 / 20] - before[before.size() / 20], hi - lo);
}

}  // namespace
}  // namespace draught::test
