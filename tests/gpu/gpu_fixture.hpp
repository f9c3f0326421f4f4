// One headless context and renderer per test process (software rasterizer, pinned by
// DRAUGHT_DEVICE=software in CTest), and scene set-up shared by the GPU tests.
#pragma once

#include "core/scene/frame.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "gpu/context.hpp"
#include "gpu/renderer.hpp"

#include <memory>

namespace draught::test {

struct Gpu {
  std::unique_ptr<gpu::HeadlessContext> context;
  std::unique_ptr<gpu::Renderer> renderer;
};

inline Gpu& gpu_instance() {
  static Gpu g = [] {
    Gpu out;
    out.context = gpu::HeadlessContext::create(gpu::DevicePreference::Software);
    out.renderer = std::make_unique<gpu::Renderer>();
    return out;
  }();
  return g;
}

inline FrameState scene_frame(const SceneRequest& req) { return make_frame(resolve_scene(req)); }

// The frame at time t of a shipped timeline (presets/timelines/), in the timeline's scene
// (seen through `camera` when given: "eye=..." "target=..." as --camera).
inline FrameState timeline_frame(const std::string& name, double t, const std::vector<std::string>& camera = {}) {
  const Timeline tl = load_timeline(name);
  SceneRequest req;
  req.camera = camera;
  req.preset = tl.preset.empty() ? req.preset : tl.preset;
  req.glass = tl.glass;
  return draught::timeline_frame(tl, resolve_scene(req), t);
}

// A scene from a request, or from a timeline at a time when `timeline` is set.
inline FrameState case_frame(const SceneRequest& req, const char* timeline, double t) {
  return timeline ? timeline_frame(timeline, t, req.camera) : scene_frame(req);
}

// A tasting flight: four drinks side by side on x, each in its own glass, 0.12 m apart
// (the content of presets/scenes/flight.json). `camera`: --camera overrides ("eye=..."),
// `sets`: --set overrides for every glass.
inline Scene flight_scene(const std::vector<std::string>& camera = {}, const std::vector<std::string>& sets = {}) {
  struct Pour {
    const char* name;
    const char* drink;
    const char* glass;
    float x;
  };
  static const Pour pours[] = {{"pilsner", "pilsner", "pilsner", -0.18f},
                               {"amber-ale", "amber-ale", "tulip", -0.06f},
                               {"stout", "stout", "nonic", 0.06f},
                               {"hefeweizen", "hefeweizen", "weizen", 0.18f}};
  Scene s;
  for (const Pour& p : pours) {
    const Params params = resolve_scene({p.drink, p.glass, sets, camera});
    if (s.objects.empty()) s.params = params;  // the surroundings, light, camera and output
    s.objects.push_back(SceneObject{p.name, Placement{{p.x, 0.0f, 0.0f}, 0.0f}, VesselObject{params}});
  }
  return s;
}

// The flight straight on (the default camera's direction), and from an angle along the
// row, where glasses are seen through each other.
inline std::vector<std::string> flight_straight_on() { return {}; }
inline std::vector<std::string> flight_at_an_angle() { return {"eye=0.5,0.2,0.3", "target=0,0.08,0"}; }

// Set by gpu_tests --bless: golden tests write their renders as the new goldens.
extern bool g_bless;

}  // namespace draught::test
