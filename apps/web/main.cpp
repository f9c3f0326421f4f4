// The web page's engine: the same scene simulation and renderer as the CLI, drawing into a
// WebGL2 canvas every animation frame. page.js drives it through the C functions below
// (strings in, strings or JSON out); errors never escape as exceptions, they come back as
// text. The page holds a scene of objects (one glass for a drink preset, several for a
// scene preset); input drives the selected one and the panel edits it.
#include "core/io/files.hpp"
#include "core/output/cutout.hpp"
#include "core/io/image.hpp"
#include "core/scene/frame.hpp"
#include "core/scene/motion.hpp"
#include "core/input/combined.hpp"
#include "core/liquid/beverage.hpp"
#include "core/params/params.hpp"
#include "core/params/preset.hpp"
#include "core/params/timeline.hpp"
#include "core/quality/adaptive_quality.hpp"
#include "core/pointcloud/cloud_files.hpp"
#include "core/pointcloud/cloud_viewing.hpp"
#include "core/scene/scene.hpp"
#include "core/sim/scene_simulation.hpp"
#include "core/text/echo.hpp"
#include "core/vessel/vessel.hpp"
#include "gpu/renderer.hpp"
#include "gpu/screen_texture.hpp"

#include <GLES3/gl3.h>
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>

namespace {

using namespace draught;
using nlohmann::json;

// How long a frame may spend refining the floor's light map once the scene holds still.
constexpr double kFloorRefineMs = 4.0;

// Where the mouse or a finger put the droplets' pointer since the last frame: CSS pixels of a
// width x height canvas (draught_pointer).
struct PendingPointer {
  double x = 0, y = 0;
  int width = 1, height = 1;
};

struct App {
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE gl = 0;
  std::string canvas;
  std::unique_ptr<gpu::Renderer> renderer;
  std::unique_ptr<SceneSimulation> sim;
  Scene scene;  // what the page edits; scene.selected is the object input drives
  InputRig rig;
  int screen_degrees = 0;
  std::string drink = "lager", glass;  // the picker's selection ("" glass: the drink's own)
  double t0 = 0, last = -1;
  long frames = 0;
  AdaptiveQuality quality;  // the backing store is CSS size x devicePixelRatio x quality.scale
  double css_w = 0, css_h = 0, dpr = 1;
  int width = 0, height = 0;
  bool context_lost = false;
  int restores = 0;         // WebGL contexts restored after a loss
  double frame_at = -1;     // now_s() when the last frame was drawn (the page's fps readout)
  double startup_ms = 0;
  // The time spent in frame() (the simulation, bubble placement, the GL calls) of the last
  // kCpuFrames frames, whose median status() reports: a shader's compile or a refined
  // floor map costs a frame seconds, which a running average carried for dozens of frames
  // (at 2 fps, most of a benchmark's run).
  static constexpr int kCpuFrames = 15;
  std::array<double, kCpuFrames> cpu_ms{};
  int cpu_count = 0;
  std::string error;  // a failure that stopped drawing
  // The page's live picture for the screen (screen.source ""): the size of the last frame
  // page.js uploaded from its <video> element or the camera, and how many it uploaded.
  int screen_w = 16, screen_h = 9;
  long screen_frames = 0;
  std::optional<PendingPointer> pointer;  // mapped by the next frame
};

App* app = nullptr;
std::string reply;  // what a C function returns lives here until the next call

const char* answer(std::string s) {
  reply = std::move(s);
  return reply.c_str();
}
// JSON replies never throw on text that is not valid UTF-8 (a quoted file, an echo): the
// bytes are replaced, so an error path cannot fail itself and leave the page without a message.
const char* answer_json(const json& j) { return answer(j.dump(-1, ' ', false, json::error_handler_t::replace)); }
double now_s() { return emscripten_get_now() / 1000.0 - (app ? app->t0 : 0); }
Viewport viewport(double w, double h) { return {std::max(1.0, w), std::max(1.0, h)}; }

// What a new scene refills: nothing, the selected glass, every glass; or `restart`, a scene
// from a file: a new simulation from time 0, as `draught render --preset FILE` starts (a
// gob or a file cloud would otherwise appear as hot as the page's clock has let it cool).
enum class Refill { none, selected, all, restart };

// A new scene from the page. The drinks keep moving; a new drink or glass is a full one
// (`refill`); other objects start afresh, their bubbles risen. The selection stays where it
// was, within the objects there are.
void use_scene(Scene s, Refill refill) {
  s.selected = std::clamp(app->scene.selected, 0, std::max(0, int(s.objects.size()) - 1));
  app->scene = s;
  if (!app->sim) return;
  if (refill == Refill::restart || app->sim->scene().objects.size() != s.objects.size()) {
    app->sim = std::make_unique<SceneSimulation>(s);
    app->sim->begin_at(now_s());
    app->sim->settle_bubbles(2.0);
    return;
  }
  app->sim->set_scene(s);
  for (int i = 0; i < int(s.objects.size()); ++i) {
    if (refill == Refill::none || (refill == Refill::selected && i != s.selected)) continue;
    if (Simulation* v = app->sim->vessel(i)) v->set_fraction(v->params().liquid.fill);
  }
}

bool has_droplets(const Scene& s) {
  return std::any_of(s.objects.begin(), s.objects.end(), [](const SceneObject& o) { return as_droplets(o) != nullptr; });
}

void select_object(int object) {
  app->scene.selected = object;
  if (app->sim) app->sim->select(object);
}

// How far the selected glass leans, in degrees (0 upright; tests and the console).
double selected_tilt_degrees() {
  const Simulation* v = app && app->sim ? app->sim->vessel(app->scene.selected) : nullptr;
  return v ? glm::degrees(tilt_angle(v->frame().pose.orientation)) : 0.0;
}

// The object seen at (x, y) CSS pixels of the canvas (vw x vh), or -1.
int pick_at(double x, double y, double vw, double vh) {
  if (!app || !app->sim) return -1;
  const int w = std::max(1, int(std::lround(vw))), h = std::max(1, int(std::lround(vh)));
  return pick_object(app->sim->frame(), x, y, w, h);
}

// The selected glass repeated side by side, a glass's width apart: a scene of several objects
// without a scene preset (tests, the console).
Scene row_of_copies(const Scene& s, int count) {
  const SceneObject& one = s.objects.at(size_t(s.selected));
  const VesselObject* v = as_vessel(one);
  if (!v) throw std::invalid_argument("the selected object is no glass");
  const double gap = 2.6 * build_vessel(v->params.glass).bound_radius;
  Scene out = s;
  out.objects.clear();
  for (int i = 0; i < count; ++i) {
    SceneObject o = one;
    o.name = one.name + "-" + std::to_string(i + 1);
    o.placement = Placement{glm::vec3(float((i - 0.5 * (count - 1)) * gap), 0, 0), 0};
    out.objects.push_back(o);
  }
  return out;
}

// "field 'objects[1].liquid.fill': expected ..., got "7"", as the CLI's --set words it. What it
// repeats of the path and the text is capped at whole UTF-8 characters (core/text/echo), so a
// pasted megabyte makes a short message.
std::string set_error(std::string_view path, const std::string& expected, std::string_view text) {
  return "field '" + shorten(path) + "': expected " + expected + ", got " + quote_input(text);
}

void resize_canvas() {
  const double s = app->quality.scale * std::max(0.5, app->dpr);
  const int w = std::clamp(int(std::lround(app->css_w * s)), 16, 4096);
  const int h = std::clamp(int(std::lround(app->css_h * s)), 16, 4096);
  if (w == app->width && h == app->height) return;
  emscripten_set_canvas_element_size(app->canvas.c_str(), w, h);
  app->width = w;
  app->height = h;
}

void frame() {
  if (!app || !app->renderer || app->context_lost) return;
  const double t = now_s();
  if (app->last >= 0 && app->frames > 3) app->quality.update((t - app->last) * 1000.0);
  app->last = t;
  resize_canvas();
  try {
    app->sim->advance(*app->rig.driver, t);
    FrameState f = app->sim->frame();
    if (f.screen.external) f.screen.set_external_size(app->screen_w, app->screen_h, f.params);  // the card takes its aspect
    if (app->quality.events_cap)
      f.params.render.max_events = std::min(f.params.render.max_events, app->quality.events_cap);
    if (app->quality.matcap) f.params.render.tier = int(RenderTier::MatCap);
    // The pointer through the camera of the picture it was moved over (this frame's), for
    // the steps of the next frames.
    if (const std::optional<PendingPointer> p = std::exchange(app->pointer, std::nullopt))
      if (const std::optional<glm::dvec2> q = droplet_pointer_at(f, p->x, p->y, p->width, p->height))
        app->sim->set_pointer(*q);
    emscripten_webgl_make_context_current(app->gl);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    app->renderer->draw(f, app->width, app->height);
    ++app->frames;
    app->frame_at = t;
    const double cpu = (now_s() - t) * 1000.0;
    app->cpu_ms[size_t(app->cpu_count++ % App::kCpuFrames)] = cpu;
  } catch (const std::exception& e) {
    app->error = e.what();
    emscripten_cancel_main_loop();
  }
}

// A lost WebGL context (a GPU reset, too many pages using WebGL, WEBGL_lose_context) takes
// every GL object with it. Drawing pauses; the scene, the simulation, the input and the
// selection live on the CPU and are kept. Returning EM_TRUE prevents the event's default,
// which is what allows the browser to restore the context.
EM_BOOL on_context_lost(int, const void*, void*) {
  app->context_lost = true;
  // Dropped now, while GL calls are no-ops: deleting its objects after the restore would
  // name objects of the old context.
  app->renderer.reset();
  return EM_TRUE;
}

// The page's renderer, at the start and after a lost context: its shaders are embedded,
// so each program is compiled when a frame first draws it (no base program up front).
std::unique_ptr<gpu::Renderer> make_web_renderer() {
  auto r = std::make_unique<gpu::Renderer>(std::filesystem::path(), gpu::Renderer::Compile::WithFirstFrame);
  // The floor's shadows: one thread (no workers), drafts while something moves, a still's
  // photons (the CLI's) once it holds still, refined over frames in batches of 1,000
  // photons for at most about 4 ms a frame (at least one batch): no frame stalls on the
  // whole, and the frames keep the speed of their drawing, which the adaptive quality
  // measures. (Batches of a draft's 5,000, one a frame, took 25 ms of each frame in this
  // one thread on a desktop, several times that on a phone.) With a tenth of the photons
  // the page's floor stayed blotched with grey.
  FloorLightSettings s;
  s.threads = 1;
  s.photons = kFloorPhotonsStill;
  r->set_floor_light(s, true, kFloorPhotonsStill / 100);
  r->set_floor_refinement(kFloorPhotonsStill / 500, kFloorRefineMs);
  r->set_moving_drafts(true);  // the MatCap tier's background while things move
  return r;
}

// The context is back, empty: programs, buffers and textures are built again (the renderer
// uploads the whole scene into its fresh textures on the next frame).
EM_BOOL on_context_restored(int, const void*, void*) {
  app->context_lost = false;
  emscripten_webgl_make_context_current(app->gl);
  try {
    app->renderer = make_web_renderer();
  } catch (const std::exception& e) {
    app->error = std::string("the WebGL context came back, but the renderer could not be rebuilt: ") + e.what();
    return EM_TRUE;
  }
  ++app->restores;
  app->last = -1;  // the pause is no frame time
  app->quality.restart();
  return EM_TRUE;
}

// The file of a video screen.source names that the page plays itself (the module decodes
// no video), in the module's file system; "" for none.
std::string app_video(const std::string& source) {
  try {
    return screen_source_played_by_app(source) ? resolve_screen_source(source).string() : std::string();
  } catch (const std::exception&) {
    return "";
  }
}

InputRig make_rig(const std::string& name) {
  InputRig rig = make_input_driver(name);
  if (rig.device) rig.device->set_screen_orientation(app->screen_degrees);
  return rig;
}

json param_row(const ParamDesc& d) {
  const std::string group = d.path.substr(0, d.path.find('.'));
  return {{"path", d.path},
          {"group", group},
          {"name", d.path.substr(group.size() + 1)},
          {"type", std::string(type_name(d.type))},
          {"default", format_param(d, d.def)},
          {"min", d.min},
          {"max", d.max},
          {"unit", d.unit},
          {"doc", d.doc},
          {"expected", expected_text(d)},
          {"choices", d.choices},
          {"scope", d.scope == ParamScope::Vessel ? "vessel" : "scene"}};
}

// The median of the last frames' CPU time (App::cpu_ms; 0 before the first frame).
double median_cpu_ms() {
  const int n = std::min(app->cpu_count, App::kCpuFrames);
  if (n == 0) return 0.0;
  std::array<double, App::kCpuFrames> v = app->cpu_ms;
  std::nth_element(v.begin(), v.begin() + n / 2, v.begin() + n);
  return v[size_t(n / 2)];
}

}  // namespace

extern "C" {

// Creates the WebGL2 context on `canvas` (a CSS selector), the renderer and the simulation
// with the default preset, and starts drawing every animation frame. fixed_scale > 0 pins
// the render scale (tests); 0 adapts it to the frame budget. "" or an error message.
EMSCRIPTEN_KEEPALIVE const char* draught_start(const char* canvas, int preserve, double fixed_scale) {
  if (app) return answer("already started");
  app = new App;
  app->canvas = canvas;
  app->t0 = emscripten_get_now() / 1000.0;
  EmscriptenWebGLContextAttributes a;
  emscripten_webgl_init_context_attributes(&a);
  a.majorVersion = 2;
  a.minorVersion = 0;
  // An alpha channel (premultiplied, the browser's default, as the renderer writes it): a
  // transparent picture (render.transparent) shows the page behind the drink; an opaque
  // one writes alpha 1 everywhere.
  a.alpha = EM_TRUE;
  a.premultipliedAlpha = EM_TRUE;
  a.depth = EM_FALSE;
  a.stencil = EM_FALSE;
  a.antialias = EM_FALSE;
  a.preserveDrawingBuffer = preserve ? EM_TRUE : EM_FALSE;
  a.powerPreference = EM_WEBGL_POWER_PREFERENCE_HIGH_PERFORMANCE;
  app->gl = emscripten_webgl_create_context(canvas, &a);
  if (app->gl <= 0) return answer(app->error = "this browser cannot create a WebGL2 context (WebGL2 is required)");
  emscripten_webgl_make_context_current(app->gl);
  emscripten_set_webglcontextlost_callback(canvas, nullptr, EM_FALSE, on_context_lost);
  emscripten_set_webglcontextrestored_callback(canvas, nullptr, EM_FALSE, on_context_restored);
  if (fixed_scale > 0) app->quality.pin(fixed_scale);
  try {
    app->scene = resolve_scene_objects(SceneRequest{});
    app->sim = std::make_unique<SceneSimulation>(app->scene);
    app->sim->begin_at(now_s());
    app->sim->settle_bubbles(2.0);
    app->rig = make_rig("mouse");
    app->renderer = make_web_renderer();
  } catch (const std::exception& e) {
    app->renderer.reset();
    return answer(app->error = e.what());
  }
  app->startup_ms = emscripten_get_now() - app->t0 * 1000.0;
  emscripten_set_main_loop(frame, 0, 0);
  return answer("");
}

// The canvas's CSS size and the device pixel ratio (page.js calls this on every resize).
EMSCRIPTEN_KEEPALIVE void draught_resize(double css_w, double css_h, double dpr) {
  if (!app) return;
  app->css_w = css_w;
  app->css_h = css_h;
  app->dpr = dpr > 0 ? dpr : 1;
  // Adaptive: start at about half a megapixel; the measured frame times take it from there.
  if (app->frames == 0) app->quality.start(css_w * css_h * app->dpr * app->dpr);
}

// scale <= 0: adaptive to budget_ms per frame; else pinned.
EMSCRIPTEN_KEEPALIVE void draught_set_quality(double scale, double budget_ms) {
  if (!app) return;
  if (budget_ms > 1) app->quality.budget_ms = budget_ms;  // (kept while pinned)
  if (scale > 0) app->quality.pin(scale);
  else app->quality.adapt();
}

// on = 0: the adaptive quality never falls to the MatCap tier (the full tier only, as
// before it; tests compare the two); 1: it does (the default).
EMSCRIPTEN_KEEPALIVE void draught_set_matcap_fallback(int on) {
  if (!app) return;
  app->quality.allow_matcap(on != 0);
}

EMSCRIPTEN_KEEPALIVE int draught_frames() { return app ? int(app->frames) : 0; }

EMSCRIPTEN_KEEPALIVE const char* draught_status() {
  if (!app) return answer("{}");
  json j = {{"frames", app->frames},
            {"time", now_s()},
            {"frame_time", app->frame_at},
            {"scale", app->quality.scale},
            {"adaptive", app->quality.adaptive},
            {"frame_ms", app->quality.shown_ms},
            {"startup_ms", app->startup_ms},
            {"cpu_ms", median_cpu_ms()},
            {"budget_ms", app->quality.budget_ms},
            {"events_cap", app->quality.events_cap},
            {"tier", app->quality.matcap || app->scene.params.render.tier == int(RenderTier::MatCap) ? "matcap" : "full"},
            {"matcap_fallback", app->quality.matcap},
            {"width", app->width},
            {"height", app->height},
            {"input", app->rig.driver ? app->rig.driver->name() : ""},
            {"drink", app->drink},
            {"glass", app->glass},
            {"objects", app->scene.objects.size()},
            {"selected", app->scene.selected},
            {"fraction", app->sim && app->sim->vessel(app->scene.selected) ? app->sim->vessel(app->scene.selected)->fraction() : 0.0},
            {"tilt", selected_tilt_degrees()},
            {"context_lost", app->context_lost},
            {"screen_mode", app->scene.params.screen.mode},
            {"screen_file", app_video(app->scene.params.screen.source)},
            {"screen_frames", app->screen_frames},
            {"screen_size", std::to_string(app->screen_w) + "x" + std::to_string(app->screen_h)},
            {"context_restores", app->restores},
            {"error", app->error}};
  return answer_json(j);
}

// Shipped presets: [{kind, name, description, suggested_glass}], glasses, drinks, scenes.
EMSCRIPTEN_KEEPALIVE const char* draught_presets() {
  try {
    json out = json::array();
    for (const Preset& p : list_presets())
      out.push_back({{"kind", p.kind}, {"name", p.name}, {"description", p.description},
                     {"suggested_glass", p.suggested_glass}});
    return answer_json(out);
  } catch (const std::exception& e) {
    return answer_json(json{{"error", e.what()}});
  }
}

// The parameter table: [{path, group, name, type, default, min, max, unit, doc, expected,
// choices, scope}]; values as text in the form draught_set_param reads. scope "vessel": each
// object has its own (objects[N].path), "scene": one for the scene.
EMSCRIPTEN_KEEPALIVE const char* draught_param_table() {
  json out = json::array();
  for (const ParamDesc& d : param_table()) out.push_back(param_row(d));
  return answer_json(out);
}

// The values the panel shows, {path: text}: the selected object's and the scene's.
EMSCRIPTEN_KEEPALIVE const char* draught_param_values() {
  json out = json::object();
  if (app && !app->scene.objects.empty()) {
    const Params doc = vessel_document(app->scene, app->scene.selected);
    for (const ParamDesc& d : param_table()) out[d.path] = format_param(d, get_param(doc, d));
  }
  return answer_json(out);
}

// What the panel says beside rows whose value is not what is in effect, {path: note}: the
// selected object's drink colour rows (core drink_colour_note), the empty ones left out.
EMSCRIPTEN_KEEPALIVE const char* draught_param_notes() {
  json out = json::object();
  if (app && !app->scene.objects.empty()) {
    const Params doc = vessel_document(app->scene, app->scene.selected);
    for (std::string_view field : kDrinkColourFields) {
      const std::string note = drink_colour_note(doc.liquid, field);
      if (!note.empty()) out["liquid." + std::string(field)] = note;
    }
  }
  return answer_json(out);
}

// One value by any path ("liquid.fill": the selected object's, "objects[2].liquid.fill",
// "env.floor"): {"value": text, "error": ""}.
EMSCRIPTEN_KEEPALIVE const char* draught_get_param(const char* path) {
  if (!app) return answer_json(json{{"error", "not started"}});
  try {
    const ParamRef ref = parse_param_ref(app->scene, path);
    return answer_json(json{{"value", format_param(*ref.desc, get_param(app->scene, ref))}, {"error", ""}});
  } catch (const ParamError& e) {
    return answer_json(json{{"error", "field '" + shorten(path) + "': expected " + e.expected}});
  }
}

// Parses, validates and applies one value; "" or the message (field, what was expected).
// "objects[N].path" sets object N's; a vessel path without the prefix sets every object's
// (as the CLI's --set), a scene path the scene's.
EMSCRIPTEN_KEEPALIVE const char* draught_set_param(const char* path, const char* text) {
  if (!app) return answer("not started");
  try {
    const ParamRef ref = parse_param_ref(app->scene, path);
    ParamValue value;
    try {
      value = parse_param_text(*ref.desc, text);
    } catch (const ParamError& e) {  // its message repeats the whole text; this one a short part
      // (A file says what is wrong with it: missing, not an image, ...)
      return answer(set_error(path, ref.desc->type == ParamType::File ? e.expected : expected_text(*ref.desc), text));
    }
    Scene s = app->scene;
    set_param(s, ref, value);
    use_scene(s, Refill::none);
    return answer("");
  } catch (const ParamError& e) {
    return answer(set_error(path, e.expected, text));
  } catch (const std::exception& e) {
    return answer(shorten(path) + ": " + e.what());
  }
}

// A decal image the page was given (`size` bytes at `data`, the file named `name`): written
// into the page's file system as /uploads/decals/N/NAME (a folder per upload: a new file never
// replaces one a glass uses) and set as the selected glass's outer (layer 0) or inner
// (layer 1) decal. "" or the error; a file the loader refuses (not a PNG, too large,
// damaged) is removed again and the glass keeps its decal.
EMSCRIPTEN_KEEPALIVE const char* draught_load_decal(const char* name, const char* data, int size, int layer) {
  if (!app) return answer("not started");
  if (size < 0 || !data || (layer != 0 && layer != 1)) return answer("draught_load_decal: bad arguments");
  static int uploads = 0;
  std::string safe;
  for (const char* c = name; *c && safe.size() < 100; ++c)
    safe += std::isalnum(static_cast<unsigned char>(*c)) || *c == '-' || *c == '_' || (*c == '.' && !safe.empty()) ? *c : '_';
  if (safe.empty()) safe = "decal.png";
  const std::filesystem::path dir = "/uploads/decals/" + std::to_string(++uploads), file = dir / safe;
  const ParamDesc* d = find_param(layer == 0 ? "decal_outer.file" : "decal_inner.file");
  try {
    std::filesystem::create_directories(dir);
    write_file_atomic(file, std::string(data, size_t(size)));
    Scene s = app->scene;
    set_param(s, ParamRef{s.selected, d}, ParamValue(file.string()));
    use_scene(s, Refill::none);
    return answer("");
  } catch (const ParamError& e) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    return answer("field '" + d->path + "' of the selected glass: expected " + e.expected);
  } catch (const std::exception& e) {
    std::error_code ec;
    std::filesystem::remove_all(dir, ec);
    return answer(shorten(name, kEchoBytes) + ": " + e.what());
  }
}

// The objects: {"selected": i, "objects": [{"name", "kind"}]}; kind "vessel", "droplets" or
// "other".
EMSCRIPTEN_KEEPALIVE const char* draught_objects() {
  json list = json::array();
  if (app)
    for (const SceneObject& o : app->scene.objects)
      list.push_back({{"name", o.name}, {"kind", as_vessel(o) ? "vessel" : as_droplets(o) ? "droplets" : "other"}});
  return answer_json(json{{"selected", app ? app->scene.selected : 0}, {"objects", list}});
}

// Selects object i (input drives it, the panel edits it); "" or the error.
EMSCRIPTEN_KEEPALIVE const char* draught_select_object(int object) {
  if (!app) return answer("not started");
  const int n = int(app->scene.objects.size());
  if (object < 0 || object >= n) return answer("no object " + std::to_string(object) + ": expected 0 to " + std::to_string(n - 1));
  select_object(object);
  return answer("");
}

// The object under (x, y) CSS pixels of a vw x vh canvas (the reference intersector on the
// frame as it stands), or -1 for the floor and the sky. Changes nothing.
EMSCRIPTEN_KEEPALIVE int draught_pick(double x, double y, double vw, double vh) { return pick_at(x, y, vw, vh); }

// A tap or click at (x, y): the object under it becomes the selected one; the floor and the
// sky keep the selection. Returns the object hit, or -1.
EMSCRIPTEN_KEEPALIVE int draught_select_at(double x, double y, double vw, double vh) {
  const int object = pick_at(x, y, vw, vh);
  if (object >= 0) select_object(object);
  return object;
}

// The droplets' pointer at (x, y) CSS pixels of a vw x vh canvas (the mouse moving over it, a
// finger on it). The next frame maps it through the camera it draws with (droplet_pointer_at
// in core/scene/frame.hpp, the desktop viewer's mapping too: where the ray there meets the
// trail's plane), and the trail follows it from then on; the last call before a frame
// counts. `dragging`: a mouse button is held, and its drag tilts the selected glass, so the
// pointer stays where it was (where the selected object is no glass the drag moves it).
// 1: taken; 0: ignored (no droplets in the scene, a glass being dragged, coordinates not
// finite, a canvas of no size). A ray that misses the plane leaves the pointer as it was.
EMSCRIPTEN_KEEPALIVE int draught_pointer(double x, double y, double vw, double vh, int dragging) {
  if (!app || !app->sim || !has_droplets(app->scene)) return 0;
  if (dragging && app->sim->vessel(app->scene.selected)) return 0;
  if (!std::isfinite(x) || !std::isfinite(y) || !(vw >= 1 && vh >= 1 && vw <= 1e6 && vh <= 1e6)) return 0;
  app->pointer = PendingPointer{x, y, int(std::lround(vw)), int(std::lround(vh))};
  return 1;
}

// The droplets trail as it stands (tests, the console): {"droplets": false} without one, else
// {"droplets": true, "pointer": [x, y] (the pointer its last step followed), "spheres":
// [[x, y, r], ...] (centres in the trail's plane from the head to the tail, m), "position":
// [x, y, z], "yaw": degrees (the plane)}.
EMSCRIPTEN_KEEPALIVE const char* draught_droplets() {
  if (!app || !app->sim) return answer_json(json{{"droplets", false}});
  for (int i = 0; i < int(app->scene.objects.size()); ++i) {
    const DropletTrail* t = app->sim->trail(i);
    if (!t) continue;
    json spheres = json::array();
    for (size_t k = 0; k < t->positions().size(); ++k)
      spheres.push_back({t->positions()[k].x, t->positions()[k].y, t->radius(int(k))});
    const Placement& at = app->scene.objects[size_t(i)].placement;
    return answer_json(json{{"droplets", true},
                            {"pointer", {t->pointer().x, t->pointer().y}},
                            {"spheres", spheres},
                            {"position", {at.position.x, at.position.y, at.position.z}},
                            {"yaw", at.yaw}});
  }
  return answer_json(json{{"droplets", false}});
}

// Tests and the console: the selected glass repeated `count` times side by side, a scene of
// several objects while no scene preset is at hand. "" or the error.
EMSCRIPTEN_KEEPALIVE const char* draught_test_row(int count) {
  if (!app) return answer("not started");
  if (count < 1 || count > kMaxSceneObjects) return answer("expected 1 to " + std::to_string(kMaxSceneObjects) + " glasses");
  try {
    use_scene(row_of_copies(app->scene, count), Refill::all);
    select_object(0);
    return answer("");
  } catch (const std::exception& e) {
    return answer(e.what());
  }
}

// A shipped drink or scene in a glass ("" = the drink's suggested glass), as the CLI's
// --preset/--glass; a scene preset with objects brings them all. "" or the error; nothing
// changes on error.
EMSCRIPTEN_KEEPALIVE const char* draught_select(const char* drink, const char* glass) {
  if (!app) return answer("not started");
  try {
    SceneRequest req;
    req.preset = drink;
    req.glass = glass;
    Scene s = resolve_scene_objects(req);
    app->drink = drink;
    app->glass = glass;
    // A scene of point clouds, or of other kinds than now, begins anew (a gob at its age);
    // a drink or glass changed in the same scene keeps the glasses' motion.
    const bool same_kinds = s.objects.size() == app->scene.objects.size() &&
                            std::equal(s.objects.begin(), s.objects.end(), app->scene.objects.begin(),
                                       [](const SceneObject& a, const SceneObject& b) { return a.kind.index() == b.kind.index(); });
    const bool clouds = std::any_of(s.objects.begin(), s.objects.end(), [](const SceneObject& o) { return as_cloud(o) != nullptr; });
    use_scene(s, same_kinds && !clouds ? Refill::all : Refill::restart);
    return answer("");
  } catch (const std::exception& e) {
    return answer(e.what());
  }
}

// A preset file's text (from the page's file input). Parsed and validated completely first;
// a glass replaces the selected object's glass, a drink its liquid, foam and bubbles; a scene
// replaces everything, as the CLI's --preset reads the file (in its suggested glass when it
// names one; its objects when it places several). {"error": "", "kind", "name"}; on error
// the state is kept.
EMSCRIPTEN_KEEPALIVE const char* draught_load_preset(const char* text, const char* file) {
  if (!app) return answer_json(json{{"error", "not started"}});
  try {
    const Preset pr = parse_preset(text, file);
    Scene s = app->scene;
    if (pr.kind == "glass" || pr.kind == "drink") {
      const Params defaults = default_params();
      Params p = vessel_document(s, s.selected);
      if (pr.kind == "glass") {
        p.glass = defaults.glass;
      } else {
        p.liquid = defaults.liquid;
        p.foam = defaults.foam;
        p.bubbles = defaults.bubbles;
      }
      apply_preset(pr, p);
      if (VesselObject* v = as_vessel(s.objects.at(size_t(s.selected)))) v->params = p;
      use_scene(s, Refill::selected);
    } else {
      // Through a file, so that the scene resolves exactly as `draught render --preset FILE`.
      const std::filesystem::path dir = "/uploads";
      std::filesystem::create_directories(dir);
      const std::filesystem::path path = dir / std::filesystem::path(file).filename().replace_extension(".json");
      write_file_atomic(path, text);
      SceneRequest req;
      req.preset = path.string();
      use_scene(resolve_scene_objects(req), Refill::restart);
    }
    return answer_json(json{{"error", ""}, {"kind", pr.kind}, {"name", shorten(pr.name)}});
  } catch (const std::exception& e) {
    return answer_json(json{{"error", e.what()}});
  }
}

// An HDR environment file from the page's file input (its bytes, `size` of them) as the
// surroundings: written to /uploads/environments/, then env.image and env.mode image, read and
// validated before anything changes. {"error": ""}; on error the file is removed and the
// state kept.
EMSCRIPTEN_KEEPALIVE const char* draught_load_environment(const char* file, const char* bytes, int size) {
  if (!app) return answer_json(json{{"error", "not started"}});
  const std::filesystem::path dir = "/uploads/environments";
  const std::filesystem::path path = dir / std::filesystem::path(file).filename();
  try {
    std::filesystem::create_directories(dir);
    write_file_atomic(path, std::string(bytes, size_t(std::max(size, 0))));
    Scene s = app->scene;
    set_param(s, parse_param_ref(s, "env.image"), ParamValue(path.string()));  // reads the image
    set_param(s, parse_param_ref(s, "env.mode"), ParamValue(std::string("image")));
    use_scene(s, Refill::none);
    return answer_json(json{{"error", ""}});
  } catch (const ParamError& e) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return answer_json(json{{"error", "env.image: expected " + e.expected}});
  } catch (const std::exception& e) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
    return answer_json(json{{"error", e.what()}});
  }
}

// A point cloud file from the page's file input (.ply, .xyz, .csv, .txt; its bytes, `size`
// of them), shown on its own: written to /uploads/clouds/, read and fitted to the view
// (core/pointcloud/cloud_viewing), and the scene preset beside it resolved as the CLI's
// --preset resolves it. {"error": "", "points": N, "scale": s}; on error both files are
// removed and the scene kept.
EMSCRIPTEN_KEEPALIVE const char* draught_load_cloud(const char* file, const char* bytes, int size) {
  if (!app) return answer_json(json{{"error", "not started"}});
  const std::filesystem::path dir = "/uploads/clouds";
  const std::filesystem::path name = std::filesystem::path(file).filename();
  const std::filesystem::path path = dir / name, preset = dir / (name.string() + ".scene.json");
  auto remove_both = [&] {
    std::error_code ec;
    std::filesystem::remove(path, ec);
    std::filesystem::remove(preset, ec);
  };
  try {
    std::filesystem::create_directories(dir);
    write_file_atomic(path, std::string(bytes, size_t(std::max(size, 0))));
    const PointCloud cloud = load_point_cloud(path);  // every error names the file and where
    if (cloud.size() == 0) throw InputError(name.string() + ": expected at least one point, found none");
    const CloudFit fit = fit_cloud_to_view(cloud);
    write_file_atomic(preset, cloud_viewing_preset(name.stem().string(), name.string(), fit));
    SceneRequest req;
    req.preset = preset.string();
    use_scene(resolve_scene_objects(req), Refill::restart);
    return answer_json(json{{"error", ""}, {"points", cloud.size()}, {"scale", fit.scale}});
  } catch (const std::exception& e) {
    remove_both();
    return answer_json(json{{"error", e.what()}});
  }
}

// Everything as a scene preset, loadable again by the page or the CLI: {"text", "error"}.
// A scene of several objects is exported whole, every object with its placement.
EMSCRIPTEN_KEEPALIVE const char* draught_export_preset(const char* name) {
  if (!app) return answer_json(json{{"error", "not started"}});
  try {
    const std::string text = scene_preset_json(app->scene, name, "Saved from the draught web page");
    return answer_json(json{{"text", text}, {"error", ""}});
  } catch (const std::exception& e) {
    return answer_json(json{{"error", e.what()}});
  }
}

// The picture as a PNG (the "Save picture" button): the frame now, drawn the CLI's way at
// width x height (its supersamples and adaptive supersampling, the tier the parameters
// ask for, not the adaptive quality's fall-backs). The PNG's bytes stay in `saved` until
// the next call: {"error", "bytes" (their address), "size", "width", "height", "ms"}.
EMSCRIPTEN_KEEPALIVE const char* draught_save_picture(int width, int height) {
  static std::string saved;
  if (!app || !app->renderer || !app->sim || app->context_lost) return answer_json(json{{"error", "not drawing"}});
  try {
    width = std::clamp(width, 16, 4096);
    height = std::clamp(height, 16, 4096);
    const double t0 = now_s();
    FrameState f = app->sim->frame();
    if (f.screen.external) f.screen.set_external_size(app->screen_w, app->screen_h, f.params);
    emscripten_webgl_make_context_current(app->gl);
    // A still's backdrop light, not a draft of moving frames, and the floor's light map
    // refined to the still's whole budget now, not a few batches a frame (set back after).
    auto still = [](bool on) {
      app->renderer->set_moving_drafts(!on);
      app->renderer->set_floor_refinement(kFloorPhotonsStill / 500, on ? 1e9 : kFloorRefineMs);
    };
    still(true);
    Image img;
    try {
      img = app->renderer->render(f, width, height);
    } catch (...) {
      still(false);
      throw;
    }
    still(false);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    saved = encode_png(png_picture(img, f.params.render.transparent));
    return answer_json(json{{"error", ""},
                            {"bytes", reinterpret_cast<std::uintptr_t>(saved.data())},
                            {"size", saved.size()},
                            {"width", width},
                            {"height", height},
                            {"ms", (now_s() - t0) * 1000.0}});
  } catch (const std::exception& e) {
    return answer_json(json{{"error", e.what()}});
  }
}

// Fills the selected glass again with a fresh head building.
EMSCRIPTEN_KEEPALIVE void draught_pour() {
  if (app && app->sim)
    if (Simulation* v = app->sim->vessel(app->scene.selected)) v->pour_over(kPourSeconds);
}

// One of input_driver_names ("mouse", "touch+gyro", ...); "" or the error.
EMSCRIPTEN_KEEPALIVE const char* draught_set_input(const char* name) {
  if (!app) return answer("not started");
  if (app->rig.driver && name == std::string(app->rig.driver->name())) return answer("");
  try {
    app->rig = make_rig(name);
    return answer("");
  } catch (const std::exception& e) {
    return answer(e.what());
  }
}

// Mouse: kind 0 press, 1 move, 2 release; button 0 left, 2 right; CSS pixels in a
// viewport of vw x vh. Without a mouse part, the left button acts as one finger.
EMSCRIPTEN_KEEPALIVE void draught_mouse(int kind, int button, double x, double y, double vw, double vh, int shift) {
  if (!app) return;
  const double t = now_s();
  const Viewport vp = viewport(vw, vh);
  const MouseButton b = button == 2 ? MouseButton::right : MouseButton::left;
  if (MouseDriver* m = app->rig.mouse) {
    if (kind == 0) m->press(t, b, x, y, vp, shift != 0);
    else if (kind == 1) m->move(t, x, y, vp);
    else m->release(t, b);
  } else if (TouchDriver* d = app->rig.touch; d && button == 0) {
    constexpr int kMouseFinger = 1 << 20;
    if (kind == 0) d->down(t, kMouseFinger, x, y, vp);
    else if (kind == 1) d->move(t, kMouseFinger, x, y, vp);
    else d->up(t, kMouseFinger);
  }
}

// Touch: kind 0 start, 1 move, 2 end, 3 cancel (every finger); id: Touch.identifier.
EMSCRIPTEN_KEEPALIVE void draught_touch(int kind, int id, double x, double y, double vw, double vh) {
  if (!app) return;
  const double t = now_s();
  const Viewport vp = viewport(vw, vh);
  if (TouchDriver* d = app->rig.touch) {
    if (kind == 0) d->down(t, id, x, y, vp);
    else if (kind == 1) d->move(t, id, x, y, vp);
    else if (kind == 2) d->up(t, id);
    else d->cancel(t);
  }
}

// devicemotion: sensor time (s), rotationRate in rad/s about the device's x, y, z (beta,
// gamma, alpha), accelerationIncludingGravity in m/s^2.
EMSCRIPTEN_KEEPALIVE void draught_device_motion(double t, double gx, double gy, double gz, double ax, double ay,
                                                double az) {
  if (app && app->rig.device) app->rig.device->motion(t, {gx, gy, gz}, {ax, ay, az});
}

// The screen's live picture from the page (screen.source "": page.js plays a video file the
// user picked, or the camera, in a <video> element). A new frame of width x height goes into
// the screen's back texture, whose GL name this returns (page.js finds its WebGLTexture in
// Emscripten's GL.textures and uploads the element with texSubImage2D, rows top-down), then
// draught_screen_commit shows it; the texture drawn from is never written. 0: no texture
// now (no renderer, a lost context) or a frame larger than a screen shows.
EMSCRIPTEN_KEEPALIVE unsigned draught_screen_begin(int width, int height) {
  if (!app || !app->renderer || app->context_lost) return 0;
  if (width < 1 || height < 1 || width > kMaxVideoSide || height > kMaxVideoSide ||
      (long long)width * height > kMaxVideoPixels)
    return 0;
  emscripten_webgl_make_context_current(app->gl);
  return app->renderer->screen_texture().begin_external(width, height);
}

// The frame draught_screen_begin gave the texture for is complete: mipmaps, then shown.
EMSCRIPTEN_KEEPALIVE void draught_screen_commit(int width, int height) {
  if (!app || !app->renderer || app->context_lost) return;
  emscripten_webgl_make_context_current(app->gl);
  app->renderer->screen_texture().commit_external();
  app->screen_w = width;
  app->screen_h = height;
  ++app->screen_frames;
}

// screen.orientation.angle
EMSCRIPTEN_KEEPALIVE void draught_screen_orientation(int degrees) {
  if (!app) return;
  app->screen_degrees = degrees;
  if (app->rig.device) app->rig.device->set_screen_orientation(degrees);
}

}  // extern "C"

int main() {
  // The presets are embedded at /presets (see cmake/web.cmake); preset_dirs() looks there.
  setenv("DRAUGHT_PRESET_DIR", "/presets", 1);
  return 0;
}
