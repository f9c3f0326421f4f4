// `draught bench`: fixed scenes, N frames each, median frame time. A benchmark, not a
// test: it prints a table and asserts nothing.
#include "commands.hpp"

#include "core/scene/frame.hpp"
#include "core/params/timeline.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

namespace draught::cli {

namespace {

struct BenchScene {
  const char* name;
  SceneRequest request;
  const char* timeline = nullptr;  // a glass in motion: this timeline's frame at `at` seconds
  double at = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int bench(int frames, const std::vector<int>& sizes, bool verbose) {
  const std::vector<BenchScene> scenes = {
      {"pint-lager", {"lager", "pint", {}, {}}},
      {"nonic-stout", {"stout", "nonic", {}, {}}},
      {"wine-red", {"red-wine", "wine", {}, {}}},
      {"tulip-amber-floorless", {"amber-ale", "tulip", {"env.floor=false"}, {}}},
      {"pint-lager-fresh-pour", {"lager", "", {}, {}}, "fresh-pour", 1.0},
      {"nonic-stout-head-closeup", {"stout", "nonic", {}, {"eye=0,0.2,0.3", "target=0,0.14,0", "vfov=22"}}},
      {"pint-lager-sloshing", {"lager", "", {}, {}}, "shake-and-settle", 1.3},
      {"wine-red-spilling", {"red-wine", "", {}, {}}, "tilt-until-spill", 3.0},
  };
  auto ctx = gpu::HeadlessContext::create();
  gpu::Renderer renderer;
  const char* threads = std::getenv("LP_NUM_THREADS");
  std::printf("renderer: %s (%s)%s%s; %d frames per row after 2 warm-up frames; %u hardware threads\n",
              ctx->renderer().c_str(), ctx->platform().c_str(), threads ? "; LP_NUM_THREADS=" : "",
              threads ? threads : "", frames, std::thread::hardware_concurrency());
  std::printf("%-26s %-9s %10s %10s %10s %8s %9s %7s %9s\n", "scene", "size", "median ms", "min ms", "max ms", "fps",
              "tests/px", "max/px", "foam/px");
  for (const auto& s : scenes) {
    std::string log;
    Params p = resolve_scene(s.request, &log);
    if (verbose) std::fprintf(stderr, "%s", log.c_str());
    p.render.supersample = 1;
    FrameState f = s.timeline ? timeline_frame(load_timeline(s.timeline), p, s.at) : make_frame(p);
    for (int size : sizes) {
      gpu::RenderTarget target(size, size, false);
      std::vector<double> ms;
      for (int i = 0; i < frames + 2; ++i) {
        auto t0 = std::chrono::steady_clock::now();
        renderer.draw(f, size, size);
        renderer.finish();
        double dt = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (i >= 2) ms.push_back(dt);
      }
      // Work per pixel: intersection tests over the whole path (analytic bound, no marching).
      gpu::DebugImage cost = renderer.render_debug(f, size, size, gpu::DebugView::Cost);
      double cost_sum = 0, cost_max = 0, foam_sum = 0;
      for (size_t i = 0; i < cost.rgba.size(); i += 4) {
        cost_sum += cost.rgba[i];
        cost_max = std::max(cost_max, double(cost.rgba[i]));
        foam_sum += cost.rgba[i + 1];  // foam march steps
      }
      const double cost_mean = cost_sum / (double(size) * size);
      double med = median(ms);
      char sz[32];
      std::snprintf(sz, sizeof sz, "%dx%d", size, size);
      std::printf("%-26s %-9s %10.2f %10.2f %10.2f %8.1f %9.1f %7.0f %9.1f\n", s.name, sz, med,
                  *std::min_element(ms.begin(), ms.end()), *std::max_element(ms.begin(), ms.end()), 1000.0 / med,
                  cost_mean, cost_max, foam_sum / (double(size) * size));
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace draught::cli
