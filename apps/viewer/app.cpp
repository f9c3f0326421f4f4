#include "app.hpp"

#include "editor.hpp"
#include "events.hpp"
#include "layout.hpp"
#include "params_panel.hpp"
#include "pointer.hpp"
#include "preset_panel.hpp"
#include "selection.hpp"
#include "window.hpp"

#include "core/io/files.hpp"
#include "core/output/cutout.hpp"
#include "core/scene/frame.hpp"
#include "core/io/image.hpp"
#include "core/input/combined.hpp"
#include "core/sim/scene_simulation.hpp"
#include "core/params/timeline.hpp"
#include "gpu/renderer.hpp"
#include "platform/sdl_gamepad.hpp"

#include <GLES3/gl3.h>
#include <imgui.h>
#include <imgui_impl_sdl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace draught::viewer {

namespace {

using gpu::DebugView;

// Quality tiers for slow machines: a lower internal resolution (scaled up when shown)
// and fewer surface interactions per path; below them the MatCap tier (render.tier
// matcap, docs/MATCAP.md), the low-cost glass at full resolution.
struct Tier {
  const char* name;
  float scale;
  int max_events;
  bool matcap = false;
};
constexpr Tier kTiers[] = {{"low", 0.5f, 6}, {"medium", 0.75f, 9}, {"high", 1.0f, 32}, {"MatCap", 1.0f, 32, true}};
// Q steps down: high -> medium -> low -> MatCap -> high.
constexpr int kNextTier[] = {3, 0, 1, 2};

// A transparent picture's premultiplied colour, drawn over what is below it.
void premultiplied_over(const ImDrawList*, const ImDrawCmd*) {
  glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

// The window behind the UI: squares of 12 px in two greys (the web page's, apps/web/style.css:
// the upper right one of each 24 px tile dark), then the picture in `texture` (a render
// target's: GL's rows bottom-up) over them.
void over_checkerboard(unsigned texture) {
  constexpr float kSquare = 12.0f;
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  list->AddRectFilled(ImVec2(0, 0), size, IM_COL32(0xa8, 0xa8, 0xa8, 0xff));
  for (int j = 0; float(j) * kSquare < size.y; ++j)
    for (int i = (j + 1) % 2; float(i) * kSquare < size.x; i += 2)
      list->AddRectFilled(ImVec2(float(i) * kSquare, float(j) * kSquare),
                          ImVec2(float(i + 1) * kSquare, float(j + 1) * kSquare), IM_COL32(0x8c, 0x8c, 0x8c, 0xff));
  list->AddCallback(premultiplied_over, nullptr);
  list->AddImage(reinterpret_cast<ImTextureID>(std::intptr_t(texture)), ImVec2(0, 0), size, ImVec2(0, 1), ImVec2(1, 0));
  list->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
}

// Screenshot mode steps the clock by a fixed 1/30 s per frame, so the picture is the same
// on a fast GPU and on llvmpipe.
constexpr double kScreenshotFps = 30;
constexpr double kSipFraction = 0.10, kSipSeconds = 1.0;  // S: drink 10 % of the glass over 1 s
constexpr double kZoomStep = 0.9;                          // camera distance per wheel click
constexpr double kWheelSettle = 0.4;  // s: wheel clicks closer together are one undo step

// Room left between the scene's free part of the window and the panel or overlay, pixels.
constexpr double kLayoutGap = 8;

constexpr const char* kKeyHelp =
    "F1 panel  Esc quit\n"
    "drag tilt  right drag swirl  wheel zoom\n"
    "move: droplets follow the mouse\n"
    "click/Tab select  Ctrl+Z undo\n"
    "R reset  P pour  S sip  C cut\n"
    "D debug view  Q quality  F12 save picture";

constexpr DebugView kViews[] = {DebugView::None, DebugView::Depth, DebugView::Normal, DebugView::Material,
                                DebugView::Cost};
constexpr const char* kViewNames[] = {"none", "depth", "normal", "material", "cost"};

// The width / height of what auto-framing fits (core/scene/frame.cpp frame_bounds): the
// glasses as they stand, widest across, with the framing's margins. Where the free part
// of the window is narrower than this, the scene's width limits it.
double framed_aspect(const FrameState& f) {
  double lo_x = 1e30, hi_x = -1e30, lo_z = 1e30, hi_z = -1e30, height = 0;
  for (const VesselFrame& v : f.vessels) {
    const double r = v.vessel.bound_radius;
    lo_x = std::min(lo_x, v.placement.position.x - r), hi_x = std::max(hi_x, v.placement.position.x + r);
    lo_z = std::min(lo_z, v.placement.position.z - r), hi_z = std::max(hi_z, v.placement.position.z + r);
    height = std::max(height, v.vessel.height);
  }
  if (f.vessels.empty()) return 1.0;
  return 1.1 * std::max(hi_x - lo_x, hi_z - lo_z) / (height + 0.024);
}

// The ImGui window being built, in window pixels.
Rect current_window_rect() {
  const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  return {at.x, at.y, at.x + size.x, at.y + size.y};
}

// Today's timelines script one glass: they drive the scene's first object (the others stand
// at rest) whichever the panel has selected.
constexpr int kTimelineObject = 0;

std::optional<Timeline> load_optional_timeline(const std::string& name) {
  if (name.empty()) return std::nullopt;
  return load_timeline(name);
}

// The scene as the CLI resolves it: flags first, then what the timeline names.
Editor make_editor(const ViewerOptions& o, const std::optional<Timeline>& tl) {
  std::string preset = o.preset, glass = o.glass;
  if (tl && !o.preset_given && !tl->preset.empty()) preset = tl->preset;
  if (tl && !o.glass_given && !tl->glass.empty()) glass = tl->glass;
  return Editor(preset, glass);
}

// The scene at time t of a timeline that drives `object`: its set and orbit actions applied
// to that object's parameters and the scene's.
Scene timeline_scene(const Timeline& tl, const Scene& base, double t, int object) {
  const Params p = tl.params_at(t, vessel_document(base, object));
  Scene s = base;
  s.params = p;
  if (VesselObject* v = as_vessel(s.objects[size_t(object)])) v->params = p;
  s.selected = object;
  return s;
}

// play_timeline (core/params/timeline.hpp) for a scene: the timeline moves the simulation's
// selected object at its placement; every other object rests on the same clock.
void play_timeline_in_scene(SceneSimulation& sim, TimelineDriver& driver, const Timeline& tl, const Scene& base,
                            double t) {
  sim.set_scene(timeline_scene(tl, base, t, sim.selected()));
  Simulation& driven = sim.selected_vessel();
  if (sim.time() == 0)
    if (auto d = tl.pours_in(0, 1e-9)) driven.pour_over(*d);  // a pour at 0 shows in frame 0
  while (sim.time() + Simulation::kStep <= t + 1e-9) {
    const double next = sim.time() + Simulation::kStep;
    if (auto d = tl.pours_in(sim.time(), next)) driven.pour_over(*d);
    sim.step(driver.sample(next), tl.drink_rate_at(next));
  }
}

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& o)
      : opt_(o),
        timeline_(load_optional_timeline(o.timeline)),
        editor_(make_editor(o, timeline_)),  // bad presets fail before a window opens
        window_("draught", o.width, o.height),
        rig_(make_input_driver(window_.has_game_controllers() ? "mouse+gamepad" : "mouse")),
        preset_state_(make_preset_panel_state()),
        show_panel_(!o.hide_panel),
        tier_(o.quality) {
    // With the controller subsystem up, the gamepad part is always there: it holds the glass
    // upright until a controller reports motion, so one plugged in later just works.
    if (rig_.gamepad) gamepad_ = std::make_unique<SdlGamepadInput>(*rig_.gamepad);
    // The floor's shadows: drafts while something moves (milliseconds), then the
    // interactive budget in five batches over as many frames once it holds still.
    interactive(true);
    applied_revision_ = editor_.revision();
    restart();
  }
  ~Viewer() {
    if (debug_tex_) glDeleteTextures(1, &debug_tex_);
  }

  int run();

 private:
  void handle(const SDL_Event&);
  void key(const SDL_Keysym&, bool repeat);
  void mouse(const SDL_Event&);
  void zoom(double clicks);
  void select(int object);
  void pick(double x, double y);
  void follow_pointer(double x, double y, bool over_ui);
  Simulation* selected_sim() { return sim_->vessel(editor_.selected()); }
  void restart();
  void advance();
  void draw_panel();
  void draw_scene(int width, int height);
  // The scene's own target at sw x sh (made again only when that size changes), bound.
  gpu::RenderTarget& scene_target(int sw, int sh);
  void draw_overlay(int width, int height);
  void lay_out();
  FrameState framed() const;  // the simulation's frame, framed in the free part of the window
  void write_screenshot(int width, int height) const;
  // The picture as the CLI draws a still (gpu::Renderer::render: supersampled, adaptive
  // supersampling, the tier the parameters ask for), the scene alone framed in the whole
  // picture, width x height, to `out` (atomically); what it says about it.
  std::string save_picture(const std::filesystem::path& out, int width, int height);
  // The renderer's settings for frames drawn as things move (on), or for a still: the
  // floor's light map at the CLI's still budget at once, the backgrounds not drafted.
  void interactive(bool on);

  const ViewerOptions opt_;
  std::optional<Timeline> timeline_;
  Editor editor_;
  Window window_;
  gpu::Renderer renderer_;  // after window_: needs its context
  std::unique_ptr<gpu::RenderTarget> scene_target_;  // low tiers and cutouts draw here, then show it
  InputRig rig_;
  std::unique_ptr<SdlGamepadInput> gamepad_;
  std::unique_ptr<SceneSimulation> sim_;
  std::unique_ptr<TimelineDriver> timeline_driver_;
  ParamsPanelState params_state_;
  PresetPanelState preset_state_;
  unsigned applied_revision_ = 0;
  bool show_panel_ = true, quit_ = false;
  bool held_[2] = {false, false};  // mouse buttons whose press went to the rig
  FrameEvents events_;              // SDL's events, a frame at a time
  ClickTracker click_;              // the left button: a click selects, a drag tilts
  std::optional<MouseMotion> pointer_motion_;  // the frame's last mouse motion, for the droplets
  int view_ = 0;                    // index into kViews
  int tier_ = 2;                    // quality: index into kTiers (high)
  double now_ = 0;                  // the app's clock, seconds: events, input samples, simulation
  double timeline_start_ = 0, last_wheel_ = -1e9;
  double sip_start_ = -1, sip_until_ = -1;  // the sip in progress, on the app's clock
  double frame_ms_ = 0;             // smoothed
  std::string note_;                // the overlay's last message (a debug view that failed, ...)
  GLuint debug_tex_ = 0;
  // What covers the window (ImGui's coordinates: window pixels), and the part of the window
  // the scene is framed in.
  Rect panel_rect_, overlay_rect_;
  PictureRect free_part_;
};

int Viewer::run() {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto last = start;
  for (int frame = 0; !quit_; ++frame) {
    const auto t = clock::now();
    const double dt_ms = std::chrono::duration<double, std::milli>(t - last).count();
    last = t;
    if (frame > 0) frame_ms_ = frame_ms_ == 0 ? dt_ms : 0.9 * frame_ms_ + 0.1 * dt_ms;
    const bool scripted = !opt_.screenshot.empty() || !opt_.picture.empty();
    now_ = scripted ? frame / kScreenshotFps : std::chrono::duration<double>(t - start).count();

    // Keys pressed and released between two frames reach ImGui over two (events.hpp).
    SDL_Event e;
    while (SDL_PollEvent(&e)) events_.push(e);
    for (const SDL_Event& frame_event : events_.take_frame()) handle(frame_event);
    window_.begin_frame();
    if (show_panel_) draw_panel();
    // A slider being dragged is one undo step, not one per frame.
    editor_.settle(ImGui::IsAnyItemActive() || now_ - last_wheel_ < kWheelSettle);
    advance();
    int w = 0, h = 0;
    window_.drawable_size(w, h);
    draw_overlay(w, h);  // before the scene: its size decides where the scene goes
    lay_out();
    draw_scene(w, h);
    window_.end_frame();
    if (scripted && frame + 1 >= opt_.frames) {
      if (!opt_.screenshot.empty()) write_screenshot(w, h);  // the back buffer, before the swap makes it undefined
      if (!opt_.picture.empty()) std::printf("%s\n", save_picture(opt_.picture, w, h).c_str());
      return 0;
    }
    window_.swap();
  }
  return 0;
}

void Viewer::handle(const SDL_Event& e) {
  feed_imgui(e);
  if (gamepad_ && gamepad_->handle(e)) return;
  switch (e.type) {
    case SDL_QUIT: quit_ = true; break;
    case SDL_KEYDOWN:
      // Only a text field takes the keys away: a focused slider still lets R, P, S work.
      if (!ImGui::GetIO().WantTextInput) key(e.key.keysym, e.key.repeat != 0);
      break;
    case SDL_MOUSEBUTTONDOWN:
    case SDL_MOUSEBUTTONUP:
    case SDL_MOUSEMOTION:
    case SDL_MOUSEWHEEL: mouse(e); break;
    case SDL_DROPFILE: {
      // A file dropped on the window: an HDR image becomes the environment, anything else
      // is loaded as a preset (each refused with its error, nothing changed).
      const std::string file = e.drop.file;
      SDL_free(e.drop.file);
      const std::string ext = std::filesystem::path(file).extension().string();
      if (ext == ".hdr" || ext == ".exr" || ext == ".HDR" || ext == ".EXR") editor_.use_environment(file);
      else editor_.load(file);
      break;
    }
    default: break;
  }
}

void Viewer::key(const SDL_Keysym& k, bool repeat) {
  const bool ctrl = k.mod & KMOD_CTRL;
  if (k.sym == SDLK_z && ctrl) {
    if (!editor_.undo()) note_ = "nothing to undo";
    return;
  }
  if (repeat || ctrl) return;
  switch (k.sym) {
    case SDLK_ESCAPE: quit_ = true; break;
    case SDLK_F1: show_panel_ = !show_panel_; break;
    case SDLK_F12: {  // the first free draught-NNNN.png in the working directory
      int w = 0, h = 0;
      window_.drawable_size(w, h);
      std::filesystem::path out;
      for (int n = 1; n < 10000 && (out.empty() || std::filesystem::exists(out)); ++n) {
        char name[32];
        std::snprintf(name, sizeof name, "draught-%04d.png", n);
        out = name;
      }
      try {
        note_ = save_picture(out, w, h);
      } catch (const std::exception& e) {
        note_ = std::string("save picture: ") + e.what();
      }
      break;
    }
    case SDLK_r: restart(); note_ = timeline_ ? "timeline restarted" : "reset: upright, refilled"; break;
    case SDLK_p:
      if (Simulation* v = selected_sim()) v->pour_over(kPourSeconds);
      note_ = "pour";
      break;
    case SDLK_TAB: select(cycle(editor_.selected(), int(editor_.scene().objects.size()), k.mod & KMOD_SHIFT ? -1 : 1)); break;
    case SDLK_s:
      if (timeline_) {
        note_ = "sip: the timeline decides what is drunk";
      } else {
        sip_start_ = now_;
        sip_until_ = now_ + kSipSeconds;
        note_ = "sip";
      }
      break;
    case SDLK_d:
      view_ = (view_ + 1) % int(std::size(kViews));  // the overlay names it
      note_.clear();
      break;
    case SDLK_q:
      tier_ = kNextTier[tier_];
      note_.clear();
      break;
    case SDLK_c: {  // the selected glass's cross-section on/off (undoable, like a panel edit)
      Scene s = editor_.scene();
      const ParamRef clip{s.selected, find_param("clip.enabled")};
      const bool on = !std::get<bool>(get_param(s, clip));
      set_param(s, clip, on);
      editor_.change(s);
      note_ = on ? "cross-section on (clip group in the panel)" : "cross-section off";
      break;
    }
    default: break;
  }
}

void Viewer::mouse(const SDL_Event& e) {
  const bool ui = ImGui::GetIO().WantCaptureMouse;
  // A click selects the glass under the pointer (in a timeline too: the panel edits it).
  if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_LEFT && !ui) click_.press(e.button.x, e.button.y);
  if (e.type == SDL_MOUSEMOTION) click_.move(e.motion.x, e.motion.y);
  if (e.type == SDL_MOUSEBUTTONUP && e.button.button == SDL_BUTTON_LEFT && click_.release())
    pick(e.button.x, e.button.y);
  if (e.type == SDL_MOUSEMOTION) follow_pointer(e.motion.x, e.motion.y, ui);
  if (timeline_) return;  // the timeline moves the glass
  int ww = 0, wh = 0;
  window_.window_size(ww, wh);
  const Viewport vp{double(ww), double(wh)};
  const auto which = [](Uint8 b) { return b == SDL_BUTTON_LEFT ? 0 : b == SDL_BUTTON_RIGHT ? 1 : -1; };
  const MouseButton buttons[] = {MouseButton::left, MouseButton::right};
  switch (e.type) {
    case SDL_MOUSEBUTTONDOWN: {
      const int b = which(e.button.button);
      if (b < 0 || ui) return;
      rig_.mouse->press(now_, buttons[b], e.button.x, e.button.y, vp, SDL_GetModState() & KMOD_SHIFT);
      held_[b] = true;
      break;
    }
    case SDL_MOUSEBUTTONUP: {
      // A drag that ends over the panel still ends: the glass must not stay tipped.
      const int b = which(e.button.button);
      if (b < 0 || !held_[b]) return;
      rig_.mouse->release(now_, buttons[b]);
      held_[b] = false;
      break;
    }
    case SDL_MOUSEMOTION:
      if (held_[0] || held_[1] || !ui) rig_.mouse->move(now_, e.motion.x, e.motion.y, vp);
      break;
    case SDL_MOUSEWHEEL:
      if (!ui) zoom(e.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -e.wheel.y : e.wheel.y);
      break;
  }
}

// A droplets trail follows the mouse moved over the picture (pointer.hpp): not over the
// panel, not while a drag tilts a glass, not while a timeline plays or a screenshot is
// rendered. The frame's last motion
// is the one that counts (advance() maps it once per frame).
void Viewer::follow_pointer(double x, double y, bool over_ui) {
  MouseMotion m;
  m.x = x;
  m.y = y;
  window_.window_size(m.window_width, m.window_height);
  m.over_ui = over_ui;
  m.dragging_glass = (held_[0] || held_[1]) && selected_sim();
  m.scripted = timeline_.has_value() || !opt_.screenshot.empty() || !opt_.picture.empty();
  pointer_motion_ = m;
}

// The object under window point (x, y) becomes the selected one; the floor or the sky
// keeps the selection.
void Viewer::pick(double x, double y) {
  int ww = 0, wh = 0;
  window_.window_size(ww, wh);
  const int object = pick_object(framed(), x + 0.5, y + 0.5, ww, wh);
  if (object >= 0 && object != editor_.selected()) select(object);
}

// The object that input drives and the panel edits. The rig carries on with the new object:
// a game controller is recentred, so the glass it takes over starts upright.
void Viewer::select(int object) {
  editor_.select(object);
  if (!timeline_) sim_->select(editor_.selected());
  if (rig_.gamepad) rig_.gamepad->recenter();
  const Scene& s = editor_.scene();
  note_ = "selected " + s.objects[size_t(s.selected)].name;
}

// Wheel up moves the camera closer along its line of sight. Auto-framing would undo any
// distance, so the first click takes over the framed camera and turns auto_frame off.
void Viewer::zoom(double clicks) {
  if (clicks == 0) return;
  Scene p = editor_.scene();
  int w = 1, h = 1;
  window_.drawable_size(w, h);
  // The camera as framed for the free part of the window (auto-framing follows its
  // aspect), so zoom starts from what is on screen.
  const int vw = std::max(1, int(std::lround(w * free_part_.width)));
  const int vh = std::max(1, int(std::lround(h * free_part_.height)));
  CameraParams c = p.params.camera.auto_frame ? sim_->frame().camera_for(vw, vh) : p.params.camera;
  const glm::vec3 back = c.eye - c.target;
  const float dist = glm::length(back);
  if (dist < 1e-6f) return;
  const float next = std::clamp(dist * float(std::pow(kZoomStep, clicks)), 0.02f, 8.0f);
  const ParamDesc* eye = find_param("camera.eye");
  const ParamDesc* target = find_param("camera.target");
  const glm::vec3 e = glm::clamp(c.target + back * (next / dist), glm::vec3(eye->min), glm::vec3(eye->max));
  try {
    set_param(p, ParamRef{-1, find_param("camera.auto_frame")}, false);
    set_param(p, ParamRef{-1, target}, c.target);
    set_param(p, ParamRef{-1, eye}, e);
  } catch (const ParamError& err) {
    note_ = std::string("zoom: ") + err.what();
    return;
  }
  editor_.change(p);
  last_wheel_ = now_;
}

// A fresh simulation: every glass upright at its place and filled to liquid.fill (or the
// timeline from 0).
void Viewer::restart() {
  sip_start_ = sip_until_ = -1;
  if (timeline_) {
    sim_ = std::make_unique<SceneSimulation>(timeline_scene(*timeline_, editor_.scene(), 0, kTimelineObject));
    timeline_driver_ = std::make_unique<TimelineDriver>(*timeline_, sim_->selected_vessel().vessel().r_outer.front());
    timeline_start_ = now_;
  } else {
    sim_ = std::make_unique<SceneSimulation>(editor_.scene());
    sim_->begin_at(now_);  // a gob begins at its age, not aged by the time the viewer has run
    if (rig_.gamepad) rig_.gamepad->recenter();  // the controller's pose now is "upright"
  }
  sim_->settle_bubbles(4.0);  // drinks that have been standing, as the CLI shows them
}

void Viewer::advance() {
  const bool changed = editor_.revision() != applied_revision_;
  applied_revision_ = editor_.revision();
  // Other objects (a preset switch, an undo): start afresh, with settled bubbles.
  if (changed && editor_.scene().objects.size() != sim_->scene().objects.size()) restart();
  if (pointer_motion_) {
    if (const std::optional<glm::dvec2> p = mouse_pointer(framed(), *pointer_motion_)) sim_->set_pointer(*p);
    pointer_motion_.reset();
  }
  if (timeline_) {
    double t = now_ - timeline_start_;
    if (t > timeline_->duration) {  // loop
      restart();
      t = 0;
    }
    if (changed) {  // the glass may have changed: the driver tips on the new foot
      sim_->set_scene(timeline_scene(*timeline_, editor_.scene(), sim_->time(), kTimelineObject));
      timeline_driver_ = std::make_unique<TimelineDriver>(*timeline_, sim_->selected_vessel().vessel().r_outer.front());
    }
    play_timeline_in_scene(*sim_, *timeline_driver_, *timeline_, editor_.scene(), t);
    return;
  }
  if (changed) sim_->set_scene(editor_.scene());
  // A sip starts and ends between simulation steps of whole frames: step to each edge with
  // the right drink rate, so a sip drinks exactly kSipFraction.
  if (sip_start_ > sim_->time()) sim_->advance(*rig_.driver, std::min(now_, sip_start_));
  if (sip_until_ > sim_->time()) sim_->advance(*rig_.driver, std::min(now_, sip_until_), kSipFraction / kSipSeconds);
  sim_->advance(*rig_.driver, now_);
}

// The scene goes where the panel and the overlay leave the most room for it (the picture is
// still drawn behind them: the camera's lens is shifted to the free part).
void Viewer::lay_out() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  std::vector<Rect> covers;
  for (const Rect& r : {show_panel_ ? panel_rect_ : Rect{}, overlay_rect_})
    if (!r.empty()) covers.push_back({r.x0 - kLayoutGap, r.y0 - kLayoutGap, r.x1 + kLayoutGap, r.y1 + kLayoutGap});
  free_part_ = picture_rect(free_rect(size.x, size.y, covers, framed_aspect(sim_->frame())), size.x, size.y);
}

FrameState Viewer::framed() const {
  FrameState f = sim_->frame();
  f.view = free_part_;
  return f;
}

void Viewer::draw_panel() {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(std::min(400.0f, io.DisplaySize.x * 0.45f), io.DisplaySize.y - 20),
                           ImGuiCond_FirstUseEver);
  const bool open = ImGui::Begin("draught");
  panel_rect_ = current_window_rect();  // its title bar only, when collapsed
  if (open) {
    preset_panel(editor_, preset_state_);
    ImGui::Separator();
    if (ImGui::CollapsingHeader("keys and mouse")) ImGui::TextUnformatted(kKeyHelp);
    ImGui::Separator();
    Scene s = editor_.scene();
    if (params_panel(s, params_state_)) editor_.change(s);
    if (s.selected != editor_.selected()) select(s.selected);  // the panel's object combo
  }
  ImGui::End();
}

void Viewer::draw_scene(int width, int height) {
  // Every object, the camera framing them all; in a timeline, its scene at this time.
  FrameState f = framed();
  const Tier& tier = kTiers[tier_];
  f.params.render.max_events = std::min(f.params.render.max_events, tier.max_events);
  if (tier.matcap) f.params.render.tier = int(RenderTier::MatCap);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const DebugView view = kViews[view_];
  const int sw = std::max(1, int(width * tier.scale)), sh = std::max(1, int(height * tier.scale));
  if (view == DebugView::None && f.params.render.transparent) {
    // A cutout is shown over a checkerboard, as image editors and the web page show one
    // (the window has no alpha of its own: over black a clear glass looked dark).
    const gpu::RenderTarget& target = scene_target(sw, sh);
    renderer_.draw(f, sw, sh);
    over_checkerboard(target.texture());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  if (view == DebugView::None && tier.scale < 1.0f) {
    scene_target(sw, sh);
    renderer_.draw(f, sw, sh);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, sw, sh, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return;
  }
  if (view == DebugView::None) {
    renderer_.draw(f, width, height);
    return;
  }
  // Debug channels are floats: they need their own target, then a readable picture of them
  // goes behind the UI as a texture.
  try {
    const Image img =
        gpu::visualize_debug(renderer_.render_debug(f, width, height, view), view, depth_range(f, width, height));
    if (!debug_tex_) {
      glGenTextures(1, &debug_tex_);
      glBindTexture(GL_TEXTURE_2D, debug_tex_);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    glBindTexture(GL_TEXTURE_2D, debug_tex_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, img.width, img.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ImGui::GetBackgroundDrawList()->AddImage(reinterpret_cast<ImTextureID>(std::intptr_t(debug_tex_)), ImVec2(0, 0),
                                             ImGui::GetIO().DisplaySize);
  } catch (const std::exception& e) {
    note_ = std::string("debug view: ") + e.what();
    view_ = 0;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    renderer_.draw(f, width, height);
  }
}

gpu::RenderTarget& Viewer::scene_target(int sw, int sh) {
  // One target kept across frames, made again only when the window or the tier resizes it.
  if (!scene_target_ || scene_target_->width() != sw || scene_target_->height() != sh) {
    scene_target_.reset();
    scene_target_ = std::make_unique<gpu::RenderTarget>(sw, sh, gpu::RenderTarget::Format::Rgba8);  // (bound)
    glBindTexture(GL_TEXTURE_2D, scene_target_->texture());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  } else {
    scene_target_->bind();
  }
  return *scene_target_;
}

void Viewer::draw_overlay(int width, int height) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 10, 10), ImGuiCond_Always, ImVec2(1, 0));
  // A fixed width (long lines wrap), so changing numbers do not move the framed scene; in a
  // window narrower than that, the window's width less the margins, so that it never starts
  // left of the window.
  const float width_px = std::max(std::min(27 * ImGui::GetFontSize(), io.DisplaySize.x - 20), 1.0f);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width_px, 0), ImVec2(width_px, io.DisplaySize.y));
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;
  if (ImGui::Begin("##overlay", nullptr, flags)) {
    if (frame_ms_ > 0) ImGui::Text("%.1f ms  %.0f fps", frame_ms_, 1000.0 / frame_ms_);
    else ImGui::Text("-- ms");
    ImGui::Text("%d x %d", width, height);
    ImGui::TextWrapped("%s", window_.renderer().c_str());
    if (timeline_)
      ImGui::TextWrapped("timeline %s: %.1f / %.1f s", timeline_->name.c_str(), sim_->time(), timeline_->duration);
    else
      ImGui::TextWrapped("input: %s%s", rig_.driver->name(), gamepad_ && gamepad_->active() >= 0 ? " (controller moving)" : "");
    // The selected glass: named where there are several (one line, so the overlay keeps
    // its size).
    const Scene& scene = editor_.scene();
    std::string which;
    if (scene.objects.size() > 1)
      which = scene.objects[size_t(scene.selected)].name + " (" + std::to_string(scene.selected + 1) + " of " +
              std::to_string(scene.objects.size()) + "): ";
    if (const Simulation* v = selected_sim())
      ImGui::TextWrapped("%s%.0f %% full, %.1f %% spilled", which.c_str(), 100.0 * v->fraction(),
                         100.0 * v->spilled());
    if (view_ != 0) ImGui::TextWrapped("debug view: %s", kViewNames[view_]);
    const Tier& tier = kTiers[tier_];
    if (tier.matcap || editor_.scene().params.render.tier == int(RenderTier::MatCap))
      ImGui::TextWrapped("quality: MatCap tier (the low-cost glass, %.0f %% resolution)", 100.0 * tier.scale);
    else
      ImGui::TextWrapped("quality %s (%.0f %% resolution, %d events)", tier.name, 100.0 * tier.scale,
                         std::min(editor_.scene().params.render.max_events, tier.max_events));
    // The note's line is always there, so a note coming and going does not resize the overlay.
    const char* hint = show_panel_ ? "keys and mouse: in the panel" : "F1: the panel, keys";
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.75f, 0.75f, 0.75f, 1.0f));
    ImGui::TextWrapped("%s", note_.empty() ? hint : note_.c_str());
    ImGui::PopStyleColor();
  }
  overlay_rect_ = current_window_rect();
  ImGui::End();
}

void Viewer::interactive(bool on) {
  // The floor's shadows while interactive: drafts while something moves (milliseconds),
  // then the interactive budget in five batches over as many frames once it holds still.
  FloorLightSettings floor;
  floor.photons = on ? kFloorPhotonsInteractive : kFloorPhotonsStill;
  renderer_.set_floor_light(floor, true, on ? kFloorPhotonsInteractive / 5 : 0);
  renderer_.set_moving_drafts(on);  // the MatCap tier's background while things move
}

std::string Viewer::save_picture(const std::filesystem::path& out, int width, int height) {
  const auto t0 = std::chrono::steady_clock::now();
  interactive(false);
  const FrameState frame = sim_->frame();
  Image img;
  try {
    img = renderer_.render(frame, std::max(width, 16), std::max(height, 16));
  } catch (...) {
    interactive(true);
    throw;
  }
  interactive(true);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());  // as the CLI does
  write_png(out, png_picture(img, frame.params.render.transparent));
  char text[256];
  std::snprintf(text, sizeof text, "saved %s (%d x %d, %.1f s)", out.string().c_str(), img.width, img.height,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return text;
}

void Viewer::write_screenshot(int width, int height) const {
  Image img{width, height, std::vector<std::uint8_t>(std::size_t(width) * std::size_t(height) * 4)};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
  // GL rows are bottom-up, PNG rows top-down; the window is opaque whatever alpha says.
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(img.px(0, y), img.px(0, y) + std::size_t(width) * 4, img.px(0, height - 1 - y));
  for (std::size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 255;
  const std::filesystem::path out(opt_.screenshot);
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());  // as the CLI does
  write_png(out, img);
  std::printf("wrote %s (%d x %d, %d frames, %s)\n", opt_.screenshot.c_str(), width, height, opt_.frames,
              window_.renderer().c_str());
  // Where the panel and the overlay are and where the scene was framed, in the screenshot's
  // pixels (x0 y0 x1 y1), for tests/viewer to check that nothing covers the glass.
  const ImVec2 ui = ImGui::GetIO().DisplaySize;
  const double sx = width / std::max(1.0f, ui.x), sy = height / std::max(1.0f, ui.y);
  const auto print = [&](const char* name, const Rect& r) {
    std::printf("layout %s %.2f %.2f %.2f %.2f\n", name, r.x0 * sx, r.y0 * sy, r.x1 * sx, r.y1 * sy);
  };
  if (show_panel_) print("panel", panel_rect_);
  print("overlay", overlay_rect_);
  const PictureRect& v = free_part_;
  print("scene", {v.x * ui.x, v.y * ui.y, (v.x + v.width) * ui.x, (v.y + v.height) * ui.y});
}

}  // namespace

int run_viewer(const ViewerOptions& o) {
  Viewer viewer(o);
  return viewer.run();
}

}  // namespace draught::viewer
