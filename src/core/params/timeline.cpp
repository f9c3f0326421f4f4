#include "core/params/timeline.hpp"

#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/params/preset.hpp"
#include "core/scene/frame.hpp"
#include "core/sim/scene_simulation.hpp"
#include "core/text/echo.hpp"
#include "core/sim/simulation.hpp"
#include "core/math/constants.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <stdexcept>

namespace draught {

using nlohmann::json;

namespace {

constexpr const char* kActionKinds = "tilt, rotate, shake, sip, orbit, set, pour, play, seek, stop, pointer";
double rad(double deg) { return deg * kPi / 180.0; }

// Progress of an action at time t, eased: 0 before, 1 after.
double progress(const TimelineAction& a, double t) {
  if (a.duration <= 0) return t >= a.at ? 1.0 : 0.0;
  const double x = std::clamp((t - a.at) / a.duration, 0.0, 1.0);
  return a.linear ? x : x * x * (3 - 2 * x);
}

// Reads a timeline's fields, collecting every mistake it can read past (a number out of
// range, an unknown key) so that one run reports them all; what it cannot read past (an
// action that is not an object, an unknown action kind) throws, and the caller collects
// that one and goes on with the next action.
struct Reader {
  const std::string& file;
  std::vector<std::string>& mistakes;
  std::string message(const std::string& field, const std::string& msg) const {
    return file + ": field '" + field + "': " + msg;
  }
  void note(const std::string& field, const std::string& msg) const { mistakes.push_back(message(field, msg)); }
  [[noreturn]] void fail(const std::string& field, const std::string& msg) const {
    throw InputError(message(field, msg));
  }
  // Runs one part of the parse; a mistake it throws is noted and the parse goes on.
  template <class F>
  void attempt(F&& part) const {
    try {
      part();
    } catch (const InputError& e) {
      mistakes.push_back(e.what());
    }
  }
  // A bad number is noted; the default (or the range's low end) stands in for it, so the
  // rest of the file can still be checked.
  double number(const json& obj, const std::string& key, const std::string& field, double lo, double hi,
                const char* unit, const double* def = nullptr) const {
    if (!obj.contains(key)) {
      if (!def) note(field, std::string("missing, expected a number in [") + fmt(lo) + ", " + fmt(hi) + "]" + unit);
      return def ? *def : lo;
    }
    const json& v = obj[key];
    if (!v.is_number() || !(v.get<double>() >= lo && v.get<double>() <= hi)) {
      note(field, std::string("expected a number in [") + fmt(lo) + ", " + fmt(hi) + "]" + unit + ", got " +
                      short_dump(v));
      return def ? *def : lo;
    }
    return v.get<double>();
  }
  std::string string(const json& obj, const std::string& key, const std::string& field) const {
    if (!obj[key].is_string()) fail(field, "expected a string, got " + short_dump(obj[key]));
    return obj[key].get<std::string>();
  }
  static std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }
};

// Every mistake noted, as one InputError: a single one word for word, several one per
// line (the first kMaxListedMistakes, then how many more).
void throw_mistakes(const std::string& file, const std::vector<std::string>& mistakes) {
  if (mistakes.empty()) return;
  if (mistakes.size() == 1) throw InputError(mistakes.front());
  constexpr size_t kMaxListedMistakes = 20;
  std::string text = file + ": " + std::to_string(mistakes.size()) + " mistakes:";
  for (size_t i = 0; i < std::min(mistakes.size(), kMaxListedMistakes); ++i) text += "\n  " + mistakes[i];
  if (mistakes.size() > kMaxListedMistakes)
    text += "\n  ... and " + std::to_string(mistakes.size() - kMaxListedMistakes) + " more";
  throw InputError(text);
}

void check_keys(const Reader& r, const json& obj, const std::string& where, std::initializer_list<const char*> keys) {
  for (auto& [key, val] : obj.items()) {
    if (std::find_if(keys.begin(), keys.end(), [&, &key = key](const char* k) { return key == k; }) != keys.end()) continue;
    std::string list;
    for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
    r.note(where + key, "unknown key, expected one of " + list);
  }
}

// "object": N or "object": "name" (checked against a scene later, by bind_timeline).
void parse_object(const Reader& r, const json& a, const std::string& at, TimelineAction& act) {
  if (!a.contains("object")) return;
  const json& o = a["object"];
  act.object_field = at + ".object";
  if (o.is_string() && !o.get<std::string>().empty()) {
    act.object_name = o.get<std::string>();
    act.object = kUnboundObject;
  } else if (o.is_number_integer() && o.get<std::int64_t>() >= 0 && o.get<std::int64_t>() < kMaxSceneObjects) {
    act.object = int(o.get<std::int64_t>());
  } else {
    r.fail(act.object_field, "expected an object index from 0 to " + std::to_string(kMaxSceneObjects - 1) +
                                 " or an object's name, got " + short_dump(o));
  }
}

TimelineAction parse_action(const Reader& r, const json& a, const std::string& at) {
  if (!a.is_object()) r.fail(at, "expected an action object, got " + short_dump(a));
  if (!a.contains("action"))
    r.fail(at + ".action", "missing, expected one of " + std::string(kActionKinds));
  const std::string kind = r.string(a, "action", at + ".action");
  TimelineAction act{};
  const double zero = 0, one = 1;
  act.at = r.number(a, "at", at + ".at", 0, 3600, " (seconds)", &zero);
  if (a.contains("ease")) {
    const std::string e = r.string(a, "ease", at + ".ease");
    if (e != "smooth" && e != "linear") r.note(at + ".ease", "expected \"smooth\" or \"linear\", got " + quote_input(e));
    act.linear = e == "linear";
  }
  auto duration = [&](double lo, const double* def) {
    return r.number(a, "duration", at + ".duration", lo, 3600, " (seconds)", def);
  };
  const std::string f = at + ".";
  if (kind == "tilt") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "angle", "toward", "object"});
    act.kind = TimelineAction::Kind::Tilt;
    act.angle = rad(r.number(a, "angle", f + "angle", 0, 135, " (degrees)"));
    act.toward = rad(r.number(a, "toward", f + "toward", -360, 360, " (degrees)", &zero));
    act.duration = duration(0, &zero);
  } else if (kind == "rotate" || kind == "orbit") {
    if (kind == "orbit" && a.contains("object"))
      r.fail(f + "object", "orbit moves the camera round the scene: it takes no object");
    check_keys(r, a, f, {"at", "action", "duration", "ease", "degrees", "object"});
    act.kind = kind == "rotate" ? TimelineAction::Kind::Rotate : TimelineAction::Kind::Orbit;
    act.degrees = rad(r.number(a, "degrees", f + "degrees", -3600, 3600, ""));
    act.duration = duration(0, &zero);
  } else if (kind == "shake") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "amplitude", "frequency", "toward", "object"});
    act.kind = TimelineAction::Kind::Shake;
    act.amplitude = r.number(a, "amplitude", f + "amplitude", 0, 0.1, " (metres)");
    act.frequency = r.number(a, "frequency", f + "frequency", 0.1, 20, " (Hz)");
    act.toward = rad(r.number(a, "toward", f + "toward", -360, 360, " (degrees)", &zero));
    act.duration = duration(0.05, nullptr);
  } else if (kind == "sip") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "amount", "object"});
    act.kind = TimelineAction::Kind::Sip;
    act.amount = r.number(a, "amount", f + "amount", 0, 1, " (fraction of the glass)");
    act.duration = duration(0.05, &one);
  } else if (kind == "set") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "param", "value", "object"});
    act.kind = TimelineAction::Kind::Set;
    if (!a.contains("param")) r.fail(f + "param", "missing, expected a parameter path such as \"liquid.srm\"");
    const std::string path = r.string(a, "param", f + "param");
    ObjectPath split;
    try {
      split = split_object_path(path);
    } catch (const ParamError& e) {
      r.fail(f + "param", "expected " + e.expected + ", got " + quote_input(path));
    }
    act.param = find_param(split.param);
    if (!act.param) r.fail(f + "param", unknown_param_message(shorten(std::string(split.param))));
    if (split.object >= 0) {
      if (a.contains("object"))
        r.fail(f + "object", "the param \"" + path + "\" already names its object: give one or the other");
      if (split.object >= kMaxSceneObjects)
        r.fail(f + "param", "expected an object index from 0 to " + std::to_string(kMaxSceneObjects - 1) +
                                " in objects[N], got " + quote_input(path));
      act.object = split.object;
      act.object_field = f + "param";
    }
    if ((split.object >= 0 || a.contains("object")) && act.param->scope == ParamScope::Scene)
      r.fail(split.object >= 0 ? f + "param" : f + "object",
             act.param->path + " belongs to the whole scene, not to one object: leave out the object");
    if (!a.contains("value")) r.fail(f + "value", "missing, expected " + expected_text(*act.param));
    act.value = param_value_from_json(*act.param, a["value"], r.file, f + "value");
    act.duration = duration(0, &zero);
  } else if (kind == "pointer") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "to", "object"});
    act.kind = TimelineAction::Kind::Pointer;
    const std::string expected = "expected [x, y]: metres right and up in the droplets' plane, each in [-2, 2]";
    if (!a.contains("to")) r.fail(f + "to", "missing, " + expected);
    const json& to = a["to"];
    if (!to.is_array() || to.size() != 2 || !to[0].is_number() || !to[1].is_number() ||
        !(std::abs(to[0].get<double>()) <= 2) || !(std::abs(to[1].get<double>()) <= 2))
      r.fail(f + "to", expected + ", got " + short_dump(to));
    act.to = {to[0].get<double>(), to[1].get<double>()};
    act.duration = duration(0, &zero);
  } else if (kind == "pour") {
    check_keys(r, a, f, {"at", "action", "object", "duration"});
    act.kind = TimelineAction::Kind::Pour;
    const double pour_default = kPourSeconds;
    act.duration = r.number(a, "duration", at + ".duration", 0, 30, " (seconds; 0 fills the glass at once)", &pour_default);
  } else if (kind == "play" || kind == "seek" || kind == "stop") {
    // The screen's source: the scene has one screen, so these take no object.
    if (a.contains("object")) r.fail(f + "object", kind + " drives the scene's screen: it takes no object");
    if (kind == "play") {
      check_keys(r, a, f, {"at", "action", "from"});
      act.kind = TimelineAction::Kind::Play;
      if (a.contains("from")) act.position = r.number(a, "from", f + "from", 0, 36000, " (seconds into the source)");
    } else if (kind == "seek") {
      check_keys(r, a, f, {"at", "action", "to"});
      act.kind = TimelineAction::Kind::Seek;
      act.position = r.number(a, "to", f + "to", 0, 36000, " (seconds into the source)");
    } else {
      check_keys(r, a, f, {"at", "action"});
      act.kind = TimelineAction::Kind::Stop;
    }
  } else {
    r.fail(at + ".action", "expected one of " + std::string(kActionKinds) + ", got " + quote_input(kind));
  }
  parse_object(r, a, at, act);
  return act;
}

glm::dvec2 lean_target(const TimelineAction& a) { return a.angle * glm::dvec2(std::cos(a.toward), std::sin(a.toward)); }

// The lean of `object` at time t, each tilt starting from from[i].
// The lean at t: the latest tilt that has started sets it, blending from where the glass
// leaned when that tilt began (`from`) to its target. `order`: the tilts in start order.
glm::dvec2 lean_with(const std::vector<TimelineAction>& actions, const std::vector<glm::dvec2>& from,
                     const std::vector<size_t>& order, double t) {
  const auto started = std::upper_bound(order.begin(), order.end(), t,
                                        [&](double time, size_t i) { return time < actions[i].at; });
  if (started == order.begin()) return glm::dvec2(0.0);
  const size_t k = *(started - 1);
  return glm::mix(from[k], lean_target(actions[k]), progress(actions[k], t));
}

// A value of a set action at progress x from `from` (numbers and vectors blend).
// A blend lands exactly on its end value, and rounding on the way never leaves the
// parameter's range (0.05 + (0.005 - 0.05) * 1 would be 0.004999999, under the minimum).
ParamValue blended(const TimelineAction& a, const ParamValue& from, double x) {
  ParamValue v = a.value;
  if (x >= 1) return v;
  const float lo = a.param->min, hi = a.param->max;
  if (auto* to = std::get_if<float>(&v))
    *to = std::clamp(float(std::get<float>(from) + (*to - std::get<float>(from)) * x), lo, hi);
  if (auto* to = std::get_if<glm::vec3>(&v))
    *to = glm::clamp(glm::mix(std::get<glm::vec3>(from), *to, float(x)), glm::vec3(lo), glm::vec3(hi));
  return v;
}

}  // namespace

Timeline parse_timeline(const std::string& text, const std::string& file) {
  const json j = parse_json_file_text(text, file);
  std::vector<std::string> mistakes;
  const Reader r{file, mistakes};
  // Not an object, or not a timeline: nothing else in it is worth reporting.
  if (!j.is_object()) throw InputError(file + ": expected a JSON object at the top level");
  if (!j.contains("draught_timeline") || j["draught_timeline"] != kTimelineFormat)
    r.fail("draught_timeline", "expected format " + std::to_string(kTimelineFormat) +
                                   (j.contains("draught_timeline") ? ", got " + short_dump(j["draught_timeline"])
                                                                   : " (missing: is this a timeline file?)"));
  check_keys(r, j, "", {"draught_timeline", "name", "description", "preset", "glass", "duration", "fps", "actions"});
  Timeline t;
  t.file = file;
  for (auto [key, out] : {std::pair{"name", &t.name}, {"description", &t.description}, {"preset", &t.preset},
                          {"glass", &t.glass}})
    if (j.contains(key)) r.attempt([&, key = key, out = out] { *out = r.string(j, key, key); });
  if (!j.contains("actions") || !j["actions"].is_array())
    r.note("actions", "expected an array of actions" + (j.contains("actions") ? ", got " + short_dump(j["actions"]) : std::string()));
  else
    for (size_t i = 0; i < j["actions"].size(); ++i)
      r.attempt([&] {
        t.actions.push_back(parse_action(r, j["actions"][i], "actions[" + std::to_string(i) + "]"));
        t.actions.back().index = int(i);
      });
  double end = 0;
  for (auto& a : t.actions) end = std::max(end, a.at + a.duration);
  const double settle = end + 2.0;
  t.duration = r.number(j, "duration", "duration", 0.01, 600, " (seconds)", &settle);
  const double no_fps = 0;
  t.fps = j.contains("fps") ? r.number(j, "fps", "fps", 1, 120, " (frames per second)") : no_fps;
  throw_mistakes(file, mistakes);
  std::stable_sort(t.actions.begin(), t.actions.end(), [](auto& a, auto& b) { return a.at < b.at; });
  t.prepare_tilts();
  return t;
}

Timeline load_timeline(const std::string& name) {
  if (name.find('/') != std::string::npos || name.ends_with(".json")) {
    if (!std::filesystem::exists(name)) throw InputError(name + ": no such timeline file");
    return parse_timeline(read_text_file(name), name);
  }
  std::string tried;
  for (auto& dir : preset_dirs()) {
    const auto p = dir / "timelines" / (name + ".json");
    if (std::filesystem::exists(p)) return parse_timeline(read_text_file(p), p.string());
    tried += (tried.empty() ? "" : ", ") + p.string();
  }
  throw InputError("no timeline named '" + name + "' (looked for " + tried + ")");
}

void Timeline::prepare_tilts() {
  // Each tilt starts from wherever the glass leans when it begins, as each object sees
  // the actions that drive it: every object alike (-1), and each one actions address.
  std::vector<int> views = {-1};
  for (auto& a : actions)
    if (a.object >= 0 && std::find(views.begin(), views.end(), a.object) == views.end()) views.push_back(a.object);
  tilt_from.clear();
  tilt_order.clear();
  for (int view : views) {
    std::vector<size_t> order;
    for (size_t i = 0; i < actions.size(); ++i)
      if (actions[i].kind == TimelineAction::Kind::Tilt && drives(actions[i], view)) order.push_back(i);
    // By start time; a later line wins a tie, as it did in file order.
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return actions[a].at < actions[b].at; });
    std::vector<glm::dvec2> from(actions.size(), glm::dvec2(0.0));
    for (size_t j = 1; j < order.size(); ++j) {  // one step each: linear in the actions
      const TimelineAction& prev = actions[order[j - 1]];
      from[order[j]] = glm::mix(from[order[j - 1]], lean_target(prev), progress(prev, actions[order[j]].at));
    }
    tilt_from[view] = std::move(from);
    tilt_order[view] = std::move(order);
  }
}

glm::dvec2 Timeline::lean_at(double t, int object) const {
  auto view = tilt_from.find(object);
  if (view == tilt_from.end()) view = tilt_from.find(-1);
  if (view == tilt_from.end() || view->second.size() != actions.size())
    throw std::logic_error("Timeline::lean_at: prepare_tilts() was not run after the actions changed");
  return lean_with(actions, view->second, tilt_order.at(view->first), t);
}

double Timeline::spin_at(double t, int object) const {
  double spin = 0;
  for (auto& a : actions)
    if (a.kind == TimelineAction::Kind::Rotate && drives(a, object)) spin += a.degrees * progress(a, t);
  return spin;
}

glm::dvec3 Timeline::shake_at(double t, int object) const {
  glm::dvec3 offset(0.0);
  for (auto& a : actions) {
    if (a.kind != TimelineAction::Kind::Shake || !drives(a, object) || t <= a.at || t >= a.at + a.duration) continue;
    const double tau = t - a.at, ramp = std::min(0.25, a.duration / 4);
    auto smooth = [](double x) { x = std::clamp(x, 0.0, 1.0); return x * x * (3 - 2 * x); };
    const double envelope = smooth(tau / ramp) * smooth((a.duration - tau) / ramp);
    const double s = a.amplitude * envelope * std::sin(2 * kPi * a.frequency * tau);
    offset += s * glm::dvec3(std::cos(a.toward), 0, std::sin(a.toward));
  }
  return offset;
}

double Timeline::drink_rate_at(double t, int object) const {
  double rate = 0;
  for (auto& a : actions)
    if (a.kind == TimelineAction::Kind::Sip && drives(a, object) && t >= a.at && t < a.at + a.duration)
      rate += a.amount / a.duration;
  return rate;
}

std::optional<double> Timeline::pours_in(double t0, double t1, int object) const {
  for (auto& a : actions)
    if (a.kind == TimelineAction::Kind::Pour && drives(a, object) && a.at >= t0 && a.at < t1) return a.duration;
  return std::nullopt;
}

namespace {
// The camera circled about the vertical through its target.
void orbit_camera(CameraParams& camera, double orbit) {
  const glm::dvec3 target(camera.target), arm = glm::dvec3(camera.eye) - target;
  const double c = std::cos(orbit), s = std::sin(orbit);
  camera.eye = glm::vec3(target + glm::dvec3(c * arm.x + s * arm.z, arm.y, -s * arm.x + c * arm.z));
}
}  // namespace

Params Timeline::params_at(double t, const Params& base) const {
  // The scene of this one glass, so there is one place that applies set and orbit actions.
  return vessel_document(scene_at(t, single_glass_scene(base)), 0);
}

Scene Timeline::scene_at(double t, const Scene& base) const {
  Scene s = base;
  double orbit = 0;
  for (auto& a : actions) {
    if (a.at > t) break;
    const double x = progress(a, t);
    if (a.kind == TimelineAction::Kind::Orbit) orbit += a.degrees * x;
    if (a.kind != TimelineAction::Kind::Set) continue;
    if (a.param->scope == ParamScope::Scene) {
      set_param(s.params, *a.param, blended(a, get_param(s.params, *a.param), x));
      continue;
    }
    // Each object blends from its own value.
    for (size_t i = 0; i < s.objects.size(); ++i)
      if (VesselObject* v = as_vessel(s.objects[i]); v && drives(a, int(i)))
        set_param(v->params, *a.param, blended(a, get_param(v->params, *a.param), x));
  }
  if (orbit != 0) orbit_camera(s.params.camera, orbit);
  s.params.screen.timeline_position =
      screen_position_at(t, base.params.screen.start, base.params.screen.playing);
  return s;
}

double Timeline::screen_position_at(double t, double start, bool playing) const {
  double position = start, since = 0;
  for (const TimelineAction& a : actions) {  // sorted by `at`
    if (a.at > t) break;
    if (a.kind != TimelineAction::Kind::Play && a.kind != TimelineAction::Kind::Seek &&
        a.kind != TimelineAction::Kind::Stop)
      continue;
    if (playing) position += a.at - since;
    since = a.at;
    if (a.kind == TimelineAction::Kind::Play) {
      playing = true;
      if (a.position >= 0) position = a.position;
    } else if (a.kind == TimelineAction::Kind::Seek) {
      position = a.position;
    } else {
      playing = false;
    }
  }
  if (playing) position += t - since;
  return std::max(position, 0.0);
}

void bind_timeline(Timeline& tl, const Scene& scene) {
  std::vector<std::string> names;
  std::string list;
  for (auto& o : scene.objects) {
    names.push_back(o.name);
    list += (list.empty() ? "\"" : ", \"") + o.name + "\"";
  }
  const std::string range = scene.objects.empty() ? std::string("no object (the scene has none)")
                                                  : object_range_text(scene) + " or a name: " + list;
  // Actions are sorted by time; mistakes are reported in file order.
  std::vector<std::pair<int, std::string>> found;
  for (auto& a : tl.actions) {
    if (a.object_field.empty()) continue;
    const std::string field = tl.file + ": field '" + a.object_field + "': ";
    if (!a.object_name.empty()) {
      const auto it = std::find(names.begin(), names.end(), a.object_name);
      if (it == names.end()) {
        const std::string near = nearest_choice(a.object_name, names);
        found.emplace_back(a.index, field + "expected an object of the scene, " + range + "; got \"" +
                                        a.object_name + "\"" + (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
        continue;
      }
      a.object = int(it - names.begin());
    } else if (a.object >= int(scene.objects.size())) {
      found.emplace_back(a.index, field + "expected " + range + ", got " + std::to_string(a.object));
    }
  }
  std::stable_sort(found.begin(), found.end(), [](auto& a, auto& b) { return a.first < b.first; });
  std::vector<std::string> mistakes;
  for (auto& f : found) mistakes.push_back(f.second);
  throw_mistakes(tl.file, mistakes);
  tl.prepare_tilts();
}

Pose TimelineDriver::pose_at(double t) const {
  const glm::dvec2 lean = timeline_->lean_at(t, object_);
  const double tilt = glm::length(lean), toward = tilt > 0 ? std::atan2(lean.y, lean.x) : 0.0;
  Pose pose = tipped_on_floor(tilt_orientation(tilt, toward, timeline_->spin_at(t, object_)), foot_radius_);
  pose.position += timeline_->shake_at(t, object_);
  return pose;
}

MotionSample TimelineDriver::sample(double t) {
  // Velocities and accelerations of the smooth scripted path.
  MotionSample m = sample_path(t, [this](double time) { return pose_at(time); });
  m.pointer = timeline_->pointer_at(t, object_);
  return m;
}

std::optional<glm::dvec2> Timeline::pointer_at(double t, int object) const {
  const TimelineAction* last = nullptr;
  glm::dvec2 from(0.0);
  for (const TimelineAction& a : actions) {  // sorted by `at`
    if (a.kind != TimelineAction::Kind::Pointer || !drives(a, object)) continue;
    if (a.at > t) break;
    if (last) from = glm::mix(from, last->to, progress(*last, a.at));  // where the pointer was then
    last = &a;
  }
  if (!last) return std::nullopt;
  return glm::mix(from, last->to, progress(*last, t));
}

void play_timeline(Simulation& sim, TimelineDriver& driver, const Timeline& tl, const Params& base, double t) {
  sim.set_params(tl.params_at(t, base));
  if (sim.time() == 0)
    if (auto d = tl.pours_in(0, 1e-9)) sim.pour_over(*d);  // a pour at 0 shows in frame 0
  while (sim.time() + Simulation::kStep <= t + 1e-9) {
    const double next = sim.time() + Simulation::kStep;
    if (auto d = tl.pours_in(sim.time(), next)) sim.pour_over(*d);
    sim.step(driver.sample(next), tl.drink_rate_at(next));
  }
}

FrameState timeline_frame(const Timeline& tl, const Params& base, double t) {
  return timeline_frame(tl, single_glass_scene(base), t);
}

std::vector<TimelineDriver> timeline_drivers(const Timeline& tl, const SceneSimulation& sim) {
  std::vector<TimelineDriver> drivers;
  for (int i = 0; i < int(sim.scene().objects.size()); ++i) {
    const Simulation* v = sim.vessel(i);
    drivers.emplace_back(tl, v ? v->vessel().r_outer.front() : 0.0, i);
  }
  return drivers;
}

void play_timeline(SceneSimulation& sim, std::vector<TimelineDriver>& drivers, const Timeline& tl, const Scene& base,
                   double t) {
  Scene now = tl.scene_at(t, base);
  now.selected = sim.selected();
  sim.set_scene(now);
  const int n = int(now.objects.size());
  if (int(drivers.size()) != n) throw std::logic_error("play_timeline: one driver per object is needed");
  auto pour = [&](double t0, double t1) {
    for (int i = 0; i < n; ++i)
      if (Simulation* v = sim.vessel(i))
        if (auto d = tl.pours_in(t0, t1, i)) v->pour_over(*d);
  };
  if (sim.time() == 0) pour(0, 1e-9);  // a pour at 0 shows in frame 0
  std::vector<MotionSample> motions(static_cast<size_t>(n));
  std::vector<double> rates(static_cast<size_t>(n));
  while (sim.time() + Simulation::kStep <= t + 1e-9) {
    const double next = sim.time() + Simulation::kStep;
    pour(sim.time(), next);
    for (int i = 0; i < n; ++i) {
      motions[size_t(i)] = drivers[size_t(i)].sample(next);
      rates[size_t(i)] = tl.drink_rate_at(next, i);
    }
    sim.step_each(motions, rates);
  }
}

FrameState timeline_frame(const Timeline& tl, const Scene& base, double t) {
  Timeline bound = tl;
  bind_timeline(bound, base);
  SceneSimulation sim(bound.scene_at(0, base));
  sim.settle_bubbles(4.0);
  std::vector<TimelineDriver> drivers = timeline_drivers(bound, sim);
  play_timeline(sim, drivers, bound, base, t);
  return sim.frame();
}

}  // namespace draught
