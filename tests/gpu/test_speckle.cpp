// The tasting flight as the README shows it (presets/scenes/flight.json: the camera a metre
// from the glasses) once had its glasses speckled with dark pixels, above the heads as much
// as in the drinks. The cause was float round-off in the wall's intersection solved from
// the camera (lib/vessel/intersect.glsl hit_wall): a hit up to 4e-5 m off the wall, more
// than the next search's tmin (2e-6 m), made the path meet the same wall again or start
// beyond it. These tests pin the cause (every path's events against the double-precision
// CPU trace) and the symptom (dark pixels among their neighbours inside the glasses).
#include "core/scene/camera.hpp"
#include "gpu_fixture.hpp"
#include "reference_path.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace draught::test {
namespace {

// The shipped flight, framed as `draught render -p flight` frames it.
FrameState shipped_flight() {
  SceneRequest req;
  req.preset = "flight";
  return make_frame(resolve_scene_objects(req));
}

// Every pixel's refracted path through the shipped flight, event by event, against the CPU
// trace: an event counts where every earlier one agrees. Float and double may fork where a
// path grazes an edge; that is a few pixels, not the hundreds of the round-off (before the
// fix, 745 of the 5500 paths through a glass differed within four events, and the first
// wall hit was up to 3.6e-5 m off; after it none, and 2.7e-7 m: the float of t itself).
TEST(Flight, PathsFromTheShippedCameraMatchTheCpuTrace) {
  Gpu& g = gpu_instance();
  const FrameState f = on_checker_floor(shipped_flight());
  const int w = 256, h = 128, events = 4;
  const SceneGeometry geo = scene_geometry(f);
  const std::vector<std::vector<PathEvent>> cpu = reference_paths(f, geo, w, h);
  std::vector<bool> alive(size_t(w * h), true);
  int glass_paths = 0, differ = 0;
  double worst_first = 0;  // the first wall hit's distance, GPU against CPU
  for (int e = 0; e < events; ++e) {
    const gpu::DebugImage gpu = g.renderer->render_debug(f, w, h, gpu::DebugView::PathEvent, e);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y * w + x);
        if (e == 0 && !cpu[i].empty() && cpu[i][0].object >= 0) ++glass_paths;
        if (!alive[i] || int(cpu[i].size()) <= e || cpu[i][0].object < 0) continue;
        const PathEvent& c = cpu[i][size_t(e)];
        const float* px = gpu.px(x, y);
        if (!same_event(px, c)) {
          ++differ;
          alive[i] = false;
          continue;
        }
        if (e == 0 && (c.m == Material::GlassOuter || c.m == Material::GlassInner))
          worst_first = std::max(worst_first, std::fabs(double(px[0]) - c.t));
      }
  }
  std::printf("[shipped flight] %d paths through a glass, %d differ from the CPU trace within %d events; worst first wall "
              "hit |dt| %.2e m\n",
              glass_paths, differ, events, worst_first);
  ASSERT_GT(glass_paths, w * h / 10);
  EXPECT_LE(differ, glass_paths / 500) << "paths fork from the CPU trace: float round-off at a wall";
  EXPECT_LT(worst_first, 1e-6) << "the first wall hit is off by a share of the next search's tmin (2e-6 m)";
}

// The picture: inside each glass's walls (pixels whose first surface is a glass's outer
// wall, 1 cm or more above its cavity's floor and below its rim, with all of their 5 x 5
// neighbourhood on the same wall) a speckle is a pixel much darker than all but four of
// its 24 neighbours (so a line of the picture, the drink's edge seen through the wall, is
// not one). Measured at 384 x 192 (supersampled 2 x 2, as shipped): 67 before the fix of
// the walls' round-off, 12 after it (sub-pixel rising bubbles drawn as pixel-sized dots:
// bubbles.frag.glsl), 0 after both.
TEST(Flight, NoDarkSpecklesInTheGlasses) {
  Gpu& g = gpu_instance();
  const FrameState f = shipped_flight();
  const int w = 384, h = 192;
  const Image img = g.renderer->render(f, w, h);
  const gpu::DebugImage mat = g.renderer->render_debug(f, w, h, gpu::DebugView::Material);
  const CameraBasis cam = camera_basis(f, w, h);
  auto lum = [&](int x, int y) {
    const std::uint8_t* p = img.px(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  };
  // The glass whose outer wall the pixel sees first, within its bowl's height; else -1.
  auto wall = [&](int x, int y) {
    const float* p = mat.px(x, y);
    const int object = int(std::lround(p[2]));
    if (std::lround(p[1]) != int(Material::GlassOuter) || object < 0) return -1;
    const VesselFrame& v = f.vessels[size_t(object)];
    const double height = camera_ray(cam, x + 0.5, y + 0.5, w, h).at(double(p[0])).y - v.pose.position.y;
    return height > v.vessel.base + 0.01 && height < v.vessel.height ? object : -1;
  };
  int inside = 0, dark = 0;
  for (int y = 2; y < h - 2; ++y)
    for (int x = 2; x < w - 2; ++x) {
      const int s = wall(x, y);
      if (s < 0) continue;
      bool interior = true;
      double nb[24];
      int n = 0;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          interior = interior && wall(x + dx, y + dy) == s;
          if (dx || dy) nb[n++] = lum(x + dx, y + dy);
        }
      if (!interior) continue;
      ++inside;
      std::sort(nb, nb + 24);
      if (nb[4] - lum(x, y) > 40.0) ++dark;
    }
  std::printf("[shipped flight %dx%d] %d pixels inside the glasses, %d dark speckles\n", w, h, inside, dark);
  ASSERT_GT(inside, w * h / 40);
  EXPECT_LE(dark, inside / 2000) << "dark speckles in the glasses";
}

}  // namespace
}  // namespace draught::test
