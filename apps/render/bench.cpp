// `draught bench`: fixed scenes, N frames each, median frame time. A benchmark, not a
// test: it prints a table and asserts nothing.
#include "commands.hpp"

#include "core/io/process.hpp"
#include "core/io/temporaries.hpp"
#include "core/io/video_source.hpp"
#include "core/condensation/wall_grid.hpp"
#include "core/pointcloud/cloud_scene.hpp"
#include "core/sim/simulation.hpp"
#include "core/scene/frame.hpp"
#include "core/params/timeline.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"
#include "gpu/screen_texture.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <thread>
#include <unistd.h>

namespace draught::cli {

namespace {

struct BenchScene {
  const char* name;
  SceneRequest request;
  const char* timeline = nullptr;  // a glass in motion: this timeline's frame at `at` seconds
  double at = 0;
  bool flight = false;  // the tasting flight (four glasses) seen with request.camera
  bool general = false;  // drawn with the general (several-object) shader path
  bool objects = false;  // a scene preset's every object (resolve_scene_objects)
  bool whole_pass = false;  // the objects' pass over the whole picture (Renderer::set_background_pass)
};

// The tasting flight of tests/gpu (pilsner, amber ale in a tulip, stout in a nonic,
// hefeweizen in a weizen, 0.12 m apart on x), built from presets until
// presets/scenes/flight.json ships; `camera` as --camera, auto-framing off.
Scene flight(const std::vector<std::string>& camera) {
  struct Pour {
    const char *name, *drink, *glass;
    float x;
  };
  static const Pour pours[] = {{"pilsner", "pilsner", "pilsner", -0.18f},
                               {"amber-ale", "amber-ale", "tulip", -0.06f},
                               {"stout", "stout", "nonic", 0.06f},
                               {"hefeweizen", "hefeweizen", "weizen", 0.18f}};
  Scene s;
  for (const Pour& p : pours) {
    const Params params = resolve_scene({p.drink, p.glass, {"camera.auto_frame=false"}, camera});
    if (s.objects.empty()) s.params = params;
    s.objects.push_back(SceneObject{p.name, Placement{{p.x, 0.0f, 0.0f}, 0.0f}, VesselObject{params}});
  }
  return s;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One scene at one size: frame times, work per pixel, covered pixels (the first surface is
// a glass) and what the glasses cost per thousand covered pixels (the frame less the
// empty view, med_empty).
struct Measured {
  double median = 0, min = 0, max = 0, tests = 0, tests_max = 0, foam = 0, per_kpx = 0;
  long covered = 0;
};

double median_ms(gpu::Renderer& renderer, const FrameState& f, int w, int h, int frames, std::vector<double>* all = nullptr);

// Pixels whose first surface is a glass.
long measure_covered(gpu::Renderer& renderer, const FrameState& f, int size) {
  const gpu::DebugImage first = renderer.render_debug(f, size, size, gpu::DebugView::Depth);
  long covered = 0;
  for (size_t i = 0; i < first.rgba.size(); i += 4) covered += first.rgba[i + 1] >= float(int(Material::GlassOuter));
  return covered;
}

// Median frame times of several frames drawn in turn, frame by frame.
std::vector<double> interleaved_medians(gpu::Renderer& renderer, const std::vector<FrameState>& states, int size,
                                        int frames) {
  gpu::RenderTarget target(size, size, gpu::RenderTarget::Format::Rgba8);
  std::vector<std::vector<double>> ms(states.size());
  for (int i = 0; i < frames + 2; ++i)
    for (size_t k = 0; k < states.size(); ++k) {
      auto t0 = std::chrono::steady_clock::now();
      renderer.draw(states[k], size, size);
      renderer.finish();
      const double dt = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      if (i >= 2) ms[k].push_back(dt);  // the first draws compile
    }
  std::vector<double> out;
  for (auto& v : ms) out.push_back(median(v));
  return out;
}

// The same frame with every object moved 5 m behind the camera: nothing of them is in
// view, but every path still tests their bounds.
FrameState out_of_view(FrameState f) {
  const glm::dvec3 back = 5.0 * glm::normalize(glm::dvec3(f.camera.eye - f.camera.target));
  for (VesselFrame& v : f.vessels) v.pose.position += back;
  return f;
}

Measured measure(gpu::Renderer& renderer, const FrameState& f, int size, int frames, double med_empty) {
  Measured m;
  std::vector<double> ms;
  m.median = median_ms(renderer, f, size, size, frames, &ms);
  m.min = *std::min_element(ms.begin(), ms.end());
  m.max = *std::max_element(ms.begin(), ms.end());
  m.covered = measure_covered(renderer, f, size);
  // Work per pixel: intersection tests over the whole path (analytic bound, no marching).
  const gpu::DebugImage cost = renderer.render_debug(f, size, size, gpu::DebugView::Cost);
  for (size_t i = 0; i < cost.rgba.size(); i += 4) {
    m.tests += cost.rgba[i];
    m.tests_max = std::max(m.tests_max, double(cost.rgba[i]));
    m.foam += cost.rgba[i + 1];  // foam march steps
  }
  const double px = double(size) * size;
  m.tests /= px;
  m.foam /= px;
  m.per_kpx = m.covered ? 1000.0 * (m.median - med_empty) / double(m.covered) : 0.0;
  return m;
}

double median_ms(gpu::Renderer& renderer, const FrameState& f, int w, int h, int frames, std::vector<double>* all) {
  gpu::RenderTarget target(w, h, gpu::RenderTarget::Format::Rgba8);
  std::vector<double> ms;
  for (int i = 0; i < frames + 2; ++i) {
    auto t0 = std::chrono::steady_clock::now();
    renderer.draw(f, w, h);
    renderer.finish();
    double dt = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (i >= 2) ms.push_back(dt);  // the first draws compile
  }
  if (all) *all = ms;
  return median(ms);
}

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// A 1280 x 720 frame of the screen's bench: a pattern that differs from frame to frame.
std::shared_ptr<const Image> frame_720p(int k) {
  Image img{1280, 720, std::vector<std::uint8_t>(size_t(1280) * 720 * 4, 255)};
  for (int y = 0; y < 720; ++y)
    for (int x = 0; x < 1280; ++x) {
      std::uint8_t* p = img.px(x, y);
      p[0] = std::uint8_t(x + 7 * k);
      p[1] = std::uint8_t(y + 13 * k);
      p[2] = std::uint8_t((x ^ y) + k);
    }
  return std::make_shared<const Image>(std::move(img));
}

// The screen's upload (gpu/screen_texture): a new 720p frame each time into the back
// texture with its mipmaps. "call": what the drawing thread spends in the upload;
// "finished": until the GPU has done it too (glFinish), the upper bound.
void bench_screen_upload(gpu::Renderer& renderer, int frames) {
  gpu::ScreenTexture tex;
  const std::shared_ptr<const Image> pictures[2] = {frame_720p(0), frame_720p(1)};
  std::vector<double> call, finished;
  ScreenFrame s;
  s.mode = ScreenMode::Card;
  for (int i = 0; i < frames + 2; ++i) {
    s.picture = pictures[i % 2];
    renderer.finish();
    const auto t0 = Clock::now();
    tex.update(s);
    const double c = ms_since(t0);
    renderer.finish();
    const double f = ms_since(t0);
    if (i >= 2) call.push_back(c), finished.push_back(f);
  }
  std::printf("%-26s %-9s %10.2f %10.2f %10.2f  (call; finished: median %.2f ms)\n", "screen-upload-720p", "1280x720",
              median(call), *std::min_element(call.begin(), call.end()), *std::max_element(call.begin(), call.end()),
              median(finished));
}

// The screen's decoding (core/io/video_source): the next 720p frame of an H.264 video read
// from ffmpeg's pipe (ffmpeg decodes in its own process, a frame ahead).
void bench_screen_decode(int frames) {
  if (find_ffmpeg("bench").empty()) {
    std::printf("%-26s (ffmpeg not found: skipped)\n", "screen-decode-720p");
    return;
  }
  const std::filesystem::path clip = temporary_path_beside(std::filesystem::temp_directory_path() / "bench.mp4");
  const std::string video = clip.string() + ".mp4";
  const std::string make = find_ffmpeg("bench") + " -nostdin -y -loglevel error -f lavfi -i testsrc2=size=1280x720:rate=25:duration=" +
                           std::to_string((frames + 12) / 25 + 1) + " -pix_fmt yuv420p '" + video + "'";
  if (std::system(make.c_str()) != 0) {
    std::printf("%-26s (ffmpeg could not make a test video: skipped)\n", "screen-decode-720p");
    return;
  }
  std::vector<double> ms;
  {
    const std::unique_ptr<VideoSource> src = open_video_source(video);
    for (int i = 1; i < frames + 3; ++i) {
      const auto t0 = Clock::now();
      src->frame(i);
      if (i >= 3) ms.push_back(ms_since(t0));
    }
  }
  std::error_code ec;
  std::filesystem::remove(video, ec);
  std::printf("%-26s %-9s %10.2f %10.2f %10.2f\n", "screen-decode-720p", "1280x720", median(ms),
              *std::min_element(ms.begin(), ms.end()), *std::max_element(ms.begin(), ms.end()));
}

// The default pint in the full tier and in the MatCap tier (docs/MATCAP.md), timed
// interleaved frame by frame in one run, so a busy machine slows both alike. The MatCap
// tier draws its background once per view: a still camera (the steady state), and a
// camera that moves every frame (two views in turn: the background drawn every frame).
void bench_tiers(gpu::Renderer& renderer, const std::vector<int>& sizes, int frames) {
  FrameState full = make_frame(resolve_scene({"lager", "pint", {}, {}}));
  full.params.render.supersample = 1;
  FrameState matcap = full;
  matcap.params.render.tier = int(RenderTier::MatCap);
  FrameState moved = matcap;
  moved.camera.eye.x += 0.002f;
  renderer.set_held_objects(true);
  for (int size : sizes) {
    const std::vector<double> still = interleaved_medians(renderer, {full, matcap}, size, frames);
    const std::vector<double> moving = interleaved_medians(renderer, {full, matcap, moved}, size, frames);
    const double moving_ms = 0.5 * (moving[1] + moving[2]);
    // As the viewer and the web page draw it: the background smaller while the view moves.
    renderer.set_moving_drafts(true);
    const std::vector<double> drafts = interleaved_medians(renderer, {full, matcap, moved}, size, frames);
    renderer.set_moving_drafts(false);
    const double drafts_ms = 0.5 * (drafts[1] + drafts[2]);
    char sz[32];
    std::snprintf(sz, sizeof sz, "%dx%d", size, size);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f\n", "pint-lager-tier-full", sz, still[0], "", "", 1000.0 / still[0]);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f  (full / matcap: %.1fx)\n", "pint-lager-tier-matcap", sz, still[1], "",
                "", 1000.0 / still[1], still[0] / still[1]);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f  (full / matcap: %.1fx; full this run: %.2f ms)\n",
                "  matcap, camera moving", sz, moving_ms, "", "", 1000.0 / moving_ms, moving[0] / moving_ms, moving[0]);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f  (full / matcap: %.1fx; full this run: %.2f ms)\n",
                "  matcap, moving, drafts", sz, drafts_ms, "", "", 1000.0 / drafts_ms, drafts[0] / drafts_ms, drafts[0]);
    std::fflush(stdout);
  }
}

// Point clouds (issue 14, docs/POINT_CLOUDS.md): one blob of 4 cm filled with 10k, 100k
// and 1M random points of hot glass, each point's blob 1.2 of their mean spacing, so the
// three cover the same pixels and look alike. What
// grows with the count is the tree's depth (the points a sample sums stay about as many).
// Also the CPU's work for 1M points: the tree built, and the texel arrays.
void bench_clouds(gpu::Renderer& renderer, const std::vector<int>& sizes, int frames) {
  SceneRequest req;
  req.preset = "molten-gob";
  FrameState base = make_frame(resolve_scene_objects(req));
  base.params.render.supersample = 1;
  std::vector<FrameState> states;
  const int counts[] = {10000, 100000, 1000000};
  std::uint64_t version = std::uint64_t(1) << 60;
  for (int n : counts) {
    auto cloud = std::make_shared<PointCloud>();
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const float radius = 0.04f, spacing = std::cbrt(4.18879f * radius * radius * radius / float(n));
    cloud->default_radius = 1.2f * spacing;
    while (int(cloud->size()) < n) {
      const glm::vec3 p(u(rng), u(rng), u(rng));
      if (glm::dot(p, p) <= 1.0f) cloud->position.push_back(glm::vec3(0.02f, 0.15f, 0.0f) + radius * p);
    }
    cloud->temperature.assign(cloud->size(), 1373.15f);
    FrameState f = base;
    f.clouds.resize(1);
    f.clouds[0].points = cloud;
    f.clouds[0].version = ++version;
    states.push_back(std::move(f));
  }
  {
    const auto t0 = std::chrono::steady_clock::now();
    CloudScene scene;
    scene.update(states.back().clouds);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-26s %-9s %10.2f  (CPU, one thread: the tree built and flattened; %.1f bytes a point on the GPU)\n",
                "cloud-1m-tree", "-", ms, double(scene.texels().gpu_bytes()) / 1e6);
  }
  // Each cloud timed on its own (drawn in turn, the frames would rebuild and upload the
  // trees every frame); a size of 1080 is drawn 1920 x 1080.
  for (int size : sizes) {
    const int w = size == 1080 ? 1920 : size, h = size;
    char sz[32];
    std::snprintf(sz, sizeof sz, "%dx%d", w, h);
    const char* names[] = {"cloud-10k", "cloud-100k", "cloud-1m"};
    std::vector<double> med;
    for (int i = 0; i < 3; ++i) {
      med.push_back(median_ms(renderer, states[size_t(i)], w, h, frames));
      std::printf("%-26s %-9s %10.2f %10s %10s %8.1f\n", names[i], sz, med.back(), "", "", 1000.0 / med.back());
    }
    std::printf("%-26s %-9s %10.2fx\n", "  1m / 10k", sz, med[2] / med[0]);
    std::fflush(stdout);
  }
}

// The droplets (issue 13) at the size, 400 x 300: the shipped preset (the trail in
// front of a pint of lager) and droplets-seed (the trail alone: the seed demo's scene, 16
// blended spheres with noise), each gathered at rest and stretched across the picture
// (the droplets-trail timeline at 0.7 s, the pointer sweeping), and the same view without
// the droplets (what the rest of the picture costs); and both drawn by the MatCap tier.
void bench_droplets(gpu::Renderer& renderer, int frames) {
  constexpr int kWidth = 400, kHeight = 300;
  const Timeline trail = load_timeline("droplets-trail");
  renderer.set_held_objects(true);
  for (const char* preset : {"droplets", "droplets-seed"}) {
    SceneRequest request;
    request.preset = preset;
    const Scene scene = resolve_scene_objects(request);
    for (const char* state : {"gathered", "stretched", "without", "gathered matcap", "stretched matcap"}) {
      const std::string s = state;
      const bool stretched = s.rfind("stretched", 0) == 0;
      FrameState f = stretched ? timeline_frame(trail, scene, 0.7) : make_frame(scene);
      f.params.render.supersample = 1;
      if (s == "without") f.droplets.clear();
      if (s.find("matcap") != std::string::npos) f.params.render.tier = int(RenderTier::MatCap);
      std::vector<double> ms;
      const double med = median_ms(renderer, f, kWidth, kHeight, frames, &ms);
      const std::string name = std::string(preset) + " " + state;
      std::printf("%-26s %-9s %10.2f %10.2f %10.2f %8.1f\n", name.c_str(), "400x300", med,
                  *std::min_element(ms.begin(), ms.end()), *std::max_element(ms.begin(), ms.end()), 1000.0 / med);
      std::fflush(stdout);
    }
  }
}

// Condensation on the default pint (issue 13: at most 30 % over the dry pint at 256 x 256
// on llvmpipe): the dry pint, the same glass beaded (condensation.* defaults) and beaded
// with its beads running (the scene's clock moving on, so every frame uploads the grid),
// drawn in turn so the ratio is measured side by side.
void bench_condensation(gpu::Renderer& renderer, const std::vector<int>& sizes, int frames) {
  SceneRequest dry{"lager", "pint", {}, {}};
  SceneRequest cold = dry;
  cold.sets = {"condensation.enabled=true"};
  FrameState a = make_frame(resolve_scene_objects(dry)), b = make_frame(resolve_scene_objects(cold));
  a.params.render.supersample = b.params.render.supersample = 1;
  // The same two in the MatCap tier, drawn in the same rounds.
  FrameState am = a, bm = b;
  am.params.render.tier = bm.params.render.tier = int(RenderTier::MatCap);
  for (int size : sizes) {
    char sz[32];
    std::snprintf(sz, sizeof sz, "%dx%d", size, size);
    const std::vector<double> med = interleaved_medians(renderer, {a, b, am, bm}, size, frames);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f\n", "pint-lager-dry", sz, med[0], "", "", 1000.0 / med[0]);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f  (cold / dry: %.3fx)\n", "pint-lager-condensation", sz, med[1], "", "",
                1000.0 / med[1], med[1] / med[0]);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f\n", "  matcap, dry", sz, med[2], "", "", 1000.0 / med[2]);
    std::printf("%-26s %-9s %10.2f %10s %10s %8.1f  (cold / dry: %.3fx)\n", "  matcap, condensation", sz, med[3], "", "",
                1000.0 / med[3], med[3] / med[2]);
    std::fflush(stdout);
  }
  // The beads running: what a frame's simulation step and upload cost (CPU).
  Simulation sim(as_vessel(resolve_scene_objects(cold).objects[0])->params);
  std::vector<double> ms;
  for (int i = 0; i < std::max(frames, 10); ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const MotionSample still;
    for (int k = 0; k < 4; ++k) sim.step(still);  // a 60 Hz frame's worth of 240 Hz steps
    const VesselFrame f = sim.frame();
    const std::vector<glm::vec4> grid = bead_grid(*f.condensation, f.vessel);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("%-26s %-9s %10.3f  (CPU: a step of the glass with its beads, and their grid packed)\n", "condensation-step", "-",
              ms[ms.size() / 2]);
}

}  // namespace

int bench(int frames, const std::vector<int>& sizes, const std::vector<std::string>& only, bool verbose) {
  const std::vector<BenchScene> scenes = {
      {"pint-lager", {"lager", "pint", {}, {}}},
      // The same with the objects' pass over the whole picture, not only where the pint can
      // show (the background pass around it): what that saves.
      {"pint-lager-whole-pass", {"lager", "pint", {}, {}}, nullptr, 0, false, false, false, true},
      // The same with two decals (docs/DECALS.md): the enamel wordmark on the front, the crest inside at the back.
      {"pint-lager-decals", {"lager", "pint", {"decal_outer.file=wordmark", "decal_outer.width=0.07", "decal_outer.color=0.75,0.06,0.05",
                                               "decal_inner.file=crest", "decal_inner.width=0.04", "decal_inner.angle=180"}, {}}},
      {"nonic-stout", {"stout", "nonic", {}, {}}},
      {"wine-red", {"red-wine", "wine", {}, {}}},
      {"tulip-amber-floorless", {"amber-ale", "tulip", {"env.floor=false"}, {}}},
      {"pint-lager-fresh-pour", {"lager", "", {}, {}}, "fresh-pour", 1.0},
      // The default pint under environment images (issue 12): a texture look-up per ray
      // leaving the scene instead of the studio's lights and sweep.
      {"pint-lager-bar", {"lager", "pint", {"env.mode=image", "env.image=bar"}, {}}},
      {"pint-lager-studio-image", {"lager", "pint", {"env.mode=image", "env.image=studio"}, {}}},
      {"nonic-stout-head-closeup", {"stout", "nonic", {}, {"eye=0,0.2,0.3", "target=0,0.14,0", "vfov=22"}}},
      {"pint-lager-sloshing", {"lager", "", {}, {}}, "shake-and-settle", 1.3},
      {"wine-red-spilling", {"red-wine", "", {}, {}}, "tilt-until-spill", 3.0},
      // Scenes of several objects. The pint with the flight's camera distance and angle,
      // so that a covered pixel costs the same in both if objects cost nothing extra.
      {"pint-lager-general-path", {"lager", "pint", {}, {}}, nullptr, 0, false, true},
      {"pint-lager-flight-camera", {"lager", "pint", {"camera.auto_frame=false"}, {"eye=0,0.17,0.8", "target=0,0.1,0", "vfov=26"}}},
      {"flight", {"", "", {}, {"eye=0,0.17,0.8", "target=0,0.1,0", "vfov=26"}}, nullptr, 0, true},
      {"flight-angle", {"", "", {}, {"eye=0.62,0.26,0.5", "target=-0.01,0.09,0", "vfov=30"}}, nullptr, 0, true},
      // The shipped flight from the same angle, and with env.reflections (its four glasses'
      // panoramas drawn every frame, 256 x 128 each: the rate 0).
      {"flight-preset-angle", {"flight", "", {}, {"eye=0.62,0.26,0.5", "target=-0.01,0.09,0", "vfov=30"}}, nullptr, 0,
       false, false, true},
      {"flight-reflections", {"flight", "", {"env.reflections=true"}, {"eye=0.62,0.26,0.5", "target=-0.01,0.09,0", "vfov=30"}},
       nullptr, 0, false, false, true},
      // The screen (issue 12): the shipped clip on a card behind the pint, and as the
      // background (the AR view); the frame is the same, so nothing is uploaded per frame.
      {"pint-lager-screen-card", {"screen-lager", "", {}, {}}},
      {"pint-lager-screen-backgr", {"lager", "pint", {"screen.mode=background", "screen.source=draught-loop"}, {}}},
  };
  auto ctx = gpu::HeadlessContext::create();
  gpu::Renderer renderer;
  const char* threads = std::getenv("LP_NUM_THREADS");
  std::printf("renderer: %s (%s)%s%s; %d frames per row after 2 warm-up frames; %u hardware threads\n",
              ctx->renderer().c_str(), ctx->platform().c_str(), threads ? "; LP_NUM_THREADS=" : "",
              threads ? threads : "", frames, std::thread::hardware_concurrency());
  std::printf("%-26s %-9s %10s %10s %10s %8s %9s %7s %9s %9s %11s\n", "scene", "size", "median ms", "min ms", "max ms",
              "fps", "tests/px", "max/px", "foam/px", "covered", "ms/kpx");
  for (const auto& s : scenes) {
    if (!only.empty() && std::find(only.begin(), only.end(), s.name) == only.end()) continue;
    std::string log;
    FrameState f;
    if (s.flight) {
      f = make_frame(flight(s.request.camera));
    } else if (s.objects) {
      f = make_frame(resolve_scene_objects(s.request));
    } else {
      Params p = resolve_scene(s.request, &log);
      if (verbose) std::fprintf(stderr, "%s", log.c_str());
      f = s.timeline ? timeline_frame(load_timeline(s.timeline), p, s.at) : make_frame(p);
    }
    f.params.render.supersample = 1;
    // The same view with no objects: what the floor and the sky cost.
    FrameState empty = f;
    empty.vessels.clear();
    renderer.set_held_objects(!s.general);
    renderer.set_background_pass(!s.whole_pass);
    for (int size : sizes) {
      const double med_empty = median_ms(renderer, empty, size, size, frames);
      const Measured m = measure(renderer, f, size, frames, med_empty);
      char sz[32];
      std::snprintf(sz, sizeof sz, "%dx%d", size, size);
      std::printf("%-26s %-9s %10.2f %10.2f %10.2f %8.1f %9.1f %7.0f %9.1f %9ld %11.4f\n", s.name, sz, m.median,
                  m.min, m.max, 1000.0 / m.median, m.tests, m.tests_max, m.foam, m.covered, m.per_kpx);
      if (s.flight) {
        // Each glass of the flight alone in the same view: what the same glasses cost
        // without each other. Timed interleaved with the flight and the empty view, frame
        // by frame, so a busy machine slows all of them alike.
        std::vector<FrameState> states = {empty, f};
        long covered = 0;
        for (const VesselFrame& v : f.vessels) {
          FrameState solo = f;
          solo.vessels = {v};
          covered += measure_covered(renderer, solo, size);
          states.push_back(std::move(solo));
        }
        const std::vector<double> med = interleaved_medians(renderer, states, size, frames);
        double alone = 0;
        for (size_t k = 2; k < med.size(); ++k) alone += med[k] - med[0];
        const double flight_kpx = 1000.0 * (med[1] - med[0]) / double(std::max(m.covered, 1L));
        const double alone_kpx = 1000.0 * alone / double(std::max(covered, 1L));
        std::printf("%-26s %-9s %10.2f %10s %10s %8s %9s %7s %9s %9ld %11.4f\n", "  (interleaved) flight", sz, med[1],
                    "", "", "", "", "", "", m.covered, flight_kpx);
        std::printf("%-26s %-9s %10s %10s %10s %8s %9s %7s %9s %9ld %11.4f  (flight / alone: %.2fx)\n",
                    "  each glass alone", sz, "", "", "", "", "", "", "", covered, alone_kpx, flight_kpx / alone_kpx);
        // The same frames with their glasses out of view (moved behind the camera): what a
        // scene with these objects costs the pixels that do not see them (the bounds tests,
        // the path loop itself). Measured against the empty view in a round of its own (six
        // states: the floor's light maps of both rounds would not fit the renderer's cache
        // together). Less that, the difference is what the covered pixels cost, so a solo
        // frame's overhead on its uncovered pixels is not counted four times for "alone".
        std::vector<FrameState> away = {empty};
        for (size_t k = 1; k < states.size(); ++k) away.push_back(out_of_view(states[k]));
        const std::vector<double> off = interleaved_medians(renderer, away, size, frames);
        double alone_own = 0;
        for (size_t k = 2; k < med.size(); ++k) alone_own += med[k] - med[0] - (off[k] - off[0]);
        const double flight_own_kpx = 1000.0 * (med[1] - med[0] - (off[1] - off[0])) / double(std::max(m.covered, 1L));
        const double alone_own_kpx = 1000.0 * alone_own / double(std::max(covered, 1L));
        std::printf("%-26s %-9s %10.2f %10s %10s %8s %9s %7s %9s %9ld %11.4f\n", "  flight, glasses away", sz, off[1],
                    "", "", "", "", "", "", m.covered, flight_own_kpx);
        std::printf("%-26s %-9s %10.2f %10s %10s %8s %9s %7s %9s %9ld %11.4f  (flight / alone, covered pixels only: %.2fx)\n",
                    "  one glass away (mean)", sz, (off[2] + off[3] + off[4] + off[5]) / 4.0, "", "", "", "", "", "",
                    covered, alone_own_kpx, flight_own_kpx / alone_own_kpx);
      }
      std::fflush(stdout);
    }
  }
  auto wanted = [&](const char* name) { return only.empty() || std::find(only.begin(), only.end(), name) != only.end(); };
  if (wanted("pint-lager-tiers")) bench_tiers(renderer, sizes, frames);
  if (wanted("clouds")) bench_clouds(renderer, sizes, frames);
  if (wanted("droplets")) bench_droplets(renderer, frames);
  if (wanted("condensation")) bench_condensation(renderer, sizes, frames);
  if (wanted("screen-upload-720p")) bench_screen_upload(renderer, frames);
  if (wanted("screen-decode-720p")) bench_screen_decode(frames);
  return 0;
}

}  // namespace draught::cli
