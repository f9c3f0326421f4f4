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

// The floor's light map of the GPU tests: fewer photons than a still's (a tenth: about
// 0.1 s a scene), since many tests draw many scenes once each. The GPU tests check how
// the picture uses the map; tests/unit/environment checks the map against the physics.
inline FloorLightSettings test_floor_light() {
  FloorLightSettings s;
  s.photons = kFloorPhotonsStill / 10;
  return s;
}

inline Gpu& gpu_instance() {
  static Gpu g = [] {
    Gpu out;
    out.context = gpu::HeadlessContext::create(gpu::DevicePreference::Software);
    out.renderer = std::make_unique<gpu::Renderer>();
    out.renderer->set_floor_light(test_floor_light());
    return out;
  }();
  return g;
}

inline FrameState scene_frame(const SceneRequest& req) { return make_frame(resolve_scene(req)); }

// The frame standing on the test environment's checker floor (presets/scenes/checker-studio.json)
// instead of the sweep: the plane y = 0, all the reference intersector (core/reference)
// knows of the floor, for tests that compare hits with it.
inline FrameState on_checker_floor(FrameState f) {
  f.params.env.backdrop = int(Backdrop::Checker);
  f.backdrop.kind = Backdrop::Checker;
  f.backdrop.plane = true;
  return f;
}

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

// How the flight is photographed (a fixed camera: auto-framing off): straight on; from
// an angle, where glasses stand in front of each other; nearly along the row, where most
// paths through one glass go on through the next.
enum class FlightView { StraightOn, AtAnAngle, AlongTheRow };

// A tasting flight: four drinks side by side on x, each in its own glass, 0.12 m apart
// (the content of presets/scenes/flight.json). `sets`: --set overrides for every glass.
inline Scene flight_scene(FlightView view = FlightView::StraightOn, std::vector<std::string> sets = {}) {
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
  const std::vector<std::string> camera =
      view == FlightView::StraightOn  ? std::vector<std::string>{"eye=0,0.17,0.8", "target=0,0.1,0", "vfov=26"}
      : view == FlightView::AtAnAngle ? std::vector<std::string>{"eye=0.62,0.26,0.5", "target=-0.01,0.09,0", "vfov=30"}
                                      : std::vector<std::string>{"eye=0.75,0.13,0.1", "target=-0.1,0.1,0", "vfov=24"};
  sets.insert(sets.begin(), "camera.auto_frame=false");
  Scene s;
  for (const Pour& p : pours) {
    const Params params = resolve_scene({p.drink, p.glass, sets, camera});
    if (s.objects.empty()) s.params = params;  // the surroundings, light, camera and output
    s.objects.push_back(SceneObject{p.name, Placement{{p.x, 0.0f, 0.0f}, 0.0f}, VesselObject{params}});
  }
  return s;
}
inline FrameState flight_front() { return make_frame(flight_scene(FlightView::StraightOn)); }
inline FrameState flight_angle() { return make_frame(flight_scene(FlightView::AtAnAngle)); }

// Set by gpu_tests --bless: golden tests write their renders as the new goldens, and
// reference comparisons path-trace and store their references (stored_reference.hpp).
extern bool g_bless;

}  // namespace draught::test
