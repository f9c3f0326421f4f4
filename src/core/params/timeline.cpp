#include "core/params/timeline.hpp"

#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/params/preset.hpp"
#include "core/text/echo.hpp"
#include "core/sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace draught {

using nlohmann::json;

namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }

// Progress of an action at time t, eased: 0 before, 1 after.
double progress(const TimelineAction& a, double t) {
  if (a.duration <= 0) return t >= a.at ? 1.0 : 0.0;
  const double x = std::clamp((t - a.at) / a.duration, 0.0, 1.0);
  return a.linear ? x : x * x * (3 - 2 * x);
}

struct Reader {
  const std::string& file;
  [[noreturn]] void fail(const std::string& field, const std::string& msg) const {
    throw InputError(file + ": field '" + field + "': " + msg);
  }
  double number(const json& obj, const std::string& key, const std::string& field, double lo, double hi,
                const char* unit, const double* def = nullptr) const {
    if (!obj.contains(key)) {
      if (def) return *def;
      fail(field, std::string("missing, expected a number in [") + fmt(lo) + ", " + fmt(hi) + "]" + unit);
    }
    const json& v = obj[key];
    if (!v.is_number() || !(v.get<double>() >= lo && v.get<double>() <= hi))
      fail(field, std::string("expected a number in [") + fmt(lo) + ", " + fmt(hi) + "]" + unit + ", got " +
                      short_dump(v));
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

void check_keys(const Reader& r, const json& obj, const std::string& where, std::initializer_list<const char*> keys) {
  for (auto& [key, val] : obj.items()) {
    if (std::find_if(keys.begin(), keys.end(), [&, &key = key](const char* k) { return key == k; }) != keys.end()) continue;
    std::string list;
    for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
    r.fail(where + key, "unknown key, expected one of " + list);
  }
}

TimelineAction parse_action(const Reader& r, const json& a, const std::string& at) {
  if (!a.is_object()) r.fail(at, "expected an action object, got " + short_dump(a));
  if (!a.contains("action"))
    r.fail(at + ".action", "missing, expected one of tilt, rotate, shake, sip, orbit, set, pour");
  const std::string kind = r.string(a, "action", at + ".action");
  TimelineAction act{};
  const double zero = 0, one = 1;
  act.at = r.number(a, "at", at + ".at", 0, 3600, " (seconds)", &zero);
  if (a.contains("ease")) {
    const std::string e = r.string(a, "ease", at + ".ease");
    if (e != "smooth" && e != "linear") r.fail(at + ".ease", "expected \"smooth\" or \"linear\", got " + quote_input(e));
    act.linear = e == "linear";
  }
  auto duration = [&](double lo, const double* def) {
    return r.number(a, "duration", at + ".duration", lo, 3600, " (seconds)", def);
  };
  const std::string f = at + ".";
  if (kind == "tilt") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "angle", "toward"});
    act.kind = TimelineAction::Kind::Tilt;
    act.angle = rad(r.number(a, "angle", f + "angle", 0, 135, " (degrees)"));
    act.toward = rad(r.number(a, "toward", f + "toward", -360, 360, " (degrees)", &zero));
    act.duration = duration(0, &zero);
  } else if (kind == "rotate" || kind == "orbit") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "degrees"});
    act.kind = kind == "rotate" ? TimelineAction::Kind::Rotate : TimelineAction::Kind::Orbit;
    act.degrees = rad(r.number(a, "degrees", f + "degrees", -3600, 3600, ""));
    act.duration = duration(0, &zero);
  } else if (kind == "shake") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "amplitude", "frequency", "toward"});
    act.kind = TimelineAction::Kind::Shake;
    act.amplitude = r.number(a, "amplitude", f + "amplitude", 0, 0.1, " (metres)");
    act.frequency = r.number(a, "frequency", f + "frequency", 0.1, 20, " (Hz)");
    act.toward = rad(r.number(a, "toward", f + "toward", -360, 360, " (degrees)", &zero));
    act.duration = duration(0.05, nullptr);
  } else if (kind == "sip") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "amount"});
    act.kind = TimelineAction::Kind::Sip;
    act.amount = r.number(a, "amount", f + "amount", 0, 1, " (fraction of the glass)");
    act.duration = duration(0.05, &one);
  } else if (kind == "set") {
    check_keys(r, a, f, {"at", "action", "duration", "ease", "param", "value"});
    act.kind = TimelineAction::Kind::Set;
    if (!a.contains("param")) r.fail(f + "param", "missing, expected a parameter path such as \"liquid.srm\"");
    const std::string path = r.string(a, "param", f + "param");
    act.param = find_param(path);
    if (!act.param) r.fail(f + "param", unknown_param_message(shorten(path)));
    if (!a.contains("value")) r.fail(f + "value", "missing, expected " + expected_text(*act.param));
    act.value = param_value_from_json(*act.param, a["value"], r.file, f + "value");
    act.duration = duration(0, &zero);
  } else if (kind == "pour") {
    check_keys(r, a, f, {"at", "action"});
    act.kind = TimelineAction::Kind::Pour;
  } else {
    r.fail(at + ".action", "expected one of tilt, rotate, shake, sip, orbit, set, pour, got " + quote_input(kind));
  }
  return act;
}

glm::dvec2 lean_target(const TimelineAction& a) { return a.angle * glm::dvec2(std::cos(a.toward), std::sin(a.toward)); }

}  // namespace

Timeline parse_timeline(const std::string& text, const std::string& file) {
  const json j = parse_json_file_text(text, file);
  const Reader r{file};
  if (!j.is_object()) throw InputError(file + ": expected a JSON object at the top level");
  check_keys(r, j, "", {"draught_timeline", "name", "description", "preset", "glass", "duration", "fps", "actions"});
  if (!j.contains("draught_timeline") || j["draught_timeline"] != kTimelineFormat)
    r.fail("draught_timeline", "expected format " + std::to_string(kTimelineFormat) +
                                   (j.contains("draught_timeline") ? ", got " + short_dump(j["draught_timeline"])
                                                                   : " (missing: is this a timeline file?)"));
  Timeline t;
  t.file = file;
  for (auto [key, out] : {std::pair{"name", &t.name}, {"description", &t.description}, {"preset", &t.preset},
                          {"glass", &t.glass}})
    if (j.contains(key)) *out = r.string(j, key, key);
  if (!j.contains("actions") || !j["actions"].is_array())
    r.fail("actions", "expected an array of actions" + (j.contains("actions") ? ", got " + short_dump(j["actions"]) : std::string()));
  for (size_t i = 0; i < j["actions"].size(); ++i)
    t.actions.push_back(parse_action(r, j["actions"][i], "actions[" + std::to_string(i) + "]"));
  std::stable_sort(t.actions.begin(), t.actions.end(), [](auto& a, auto& b) { return a.at < b.at; });
  // Each tilt starts from wherever the glass leans when it begins.
  for (auto& a : t.actions)
    if (a.kind == TimelineAction::Kind::Tilt) a.tilt_from = t.lean_at(a.at);
  double end = 0;
  for (auto& a : t.actions) end = std::max(end, a.at + a.duration);
  const double settle = end + 2.0;
  t.duration = r.number(j, "duration", "duration", 0.01, 600, " (seconds)", &settle);
  const double no_fps = 0;
  t.fps = j.contains("fps") ? r.number(j, "fps", "fps", 1, 120, " (frames per second)") : no_fps;
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

glm::dvec2 Timeline::lean_at(double t) const {
  glm::dvec2 lean(0.0);
  for (auto& a : actions) {
    if (a.at > t) break;
    if (a.kind == TimelineAction::Kind::Tilt) lean = glm::mix(a.tilt_from, lean_target(a), progress(a, t));
  }
  return lean;
}

double Timeline::spin_at(double t) const {
  double spin = 0;
  for (auto& a : actions)
    if (a.kind == TimelineAction::Kind::Rotate) spin += a.degrees * progress(a, t);
  return spin;
}

glm::dvec3 Timeline::shake_at(double t) const {
  glm::dvec3 offset(0.0);
  for (auto& a : actions) {
    if (a.kind != TimelineAction::Kind::Shake || t <= a.at || t >= a.at + a.duration) continue;
    const double tau = t - a.at, ramp = std::min(0.25, a.duration / 4);
    auto smooth = [](double x) { x = std::clamp(x, 0.0, 1.0); return x * x * (3 - 2 * x); };
    const double envelope = smooth(tau / ramp) * smooth((a.duration - tau) / ramp);
    const double s = a.amplitude * envelope * std::sin(2 * kPi * a.frequency * tau);
    offset += s * glm::dvec3(std::cos(a.toward), 0, std::sin(a.toward));
  }
  return offset;
}

double Timeline::drink_rate_at(double t) const {
  double rate = 0;
  for (auto& a : actions)
    if (a.kind == TimelineAction::Kind::Sip && t >= a.at && t < a.at + a.duration) rate += a.amount / a.duration;
  return rate;
}

bool Timeline::pours_in(double t0, double t1) const {
  for (auto& a : actions)
    if (a.kind == TimelineAction::Kind::Pour && a.at >= t0 && a.at < t1) return true;
  return false;
}

Params Timeline::params_at(double t, const Params& base) const {
  Params p = base;
  double orbit = 0;
  for (auto& a : actions) {
    if (a.at > t) break;
    const double x = progress(a, t);
    if (a.kind == TimelineAction::Kind::Orbit) orbit += a.degrees * x;
    if (a.kind != TimelineAction::Kind::Set) continue;
    ParamValue v = a.value;
    const ParamValue from = get_param(p, *a.param);
    if (auto* to = std::get_if<float>(&v)) *to = float(std::get<float>(from) + (*to - std::get<float>(from)) * x);
    if (auto* to = std::get_if<glm::vec3>(&v)) *to = glm::mix(std::get<glm::vec3>(from), *to, float(x));
    set_param(p, *a.param, v);
  }
  if (orbit != 0) {  // the camera circles the vertical through its target
    const glm::dvec3 target(p.camera.target), arm = glm::dvec3(p.camera.eye) - target;
    const double c = std::cos(orbit), s = std::sin(orbit);
    p.camera.eye = glm::vec3(target + glm::dvec3(c * arm.x + s * arm.z, arm.y, -s * arm.x + c * arm.z));
  }
  return p;
}

Pose TimelineDriver::pose_at(double t) const {
  const glm::dvec2 lean = timeline_.lean_at(t);
  const double tilt = glm::length(lean), toward = tilt > 0 ? std::atan2(lean.y, lean.x) : 0.0;
  Pose pose = tipped_on_floor(tilt_orientation(tilt, toward, timeline_.spin_at(t)), foot_radius_);
  pose.position += timeline_.shake_at(t);
  return pose;
}

MotionSample TimelineDriver::sample(double t) {
  // Velocities and accelerations by central differences of the smooth scripted path.
  constexpr double h = 1e-3;
  MotionSample m;
  m.time = t;
  m.pose = pose_at(t);
  const Pose before = pose_at(t - h), after = pose_at(t + h);
  const glm::dquat dq = after.orientation * glm::inverse(before.orientation);
  const double angle = 2.0 * std::acos(std::clamp(std::abs(dq.w), 0.0, 1.0));
  const glm::dvec3 axis(dq.x, dq.y, dq.z);
  if (glm::length(axis) > 1e-15) m.angular_velocity = glm::normalize(axis) * (dq.w < 0 ? -angle : angle) / (2 * h);
  m.linear_acceleration = (after.position - 2.0 * m.pose.position + before.position) / (h * h);
  return sanitize(m);
}

void play_timeline(Simulation& sim, TimelineDriver& driver, const Timeline& tl, const Params& base, double t) {
  sim.set_params(tl.params_at(t, base));
  if (sim.time() == 0 && tl.pours_in(0, 1e-9)) sim.pour();  // a pour at 0 shows in frame 0
  while (sim.time() + Simulation::kStep <= t + 1e-9) {
    const double next = sim.time() + Simulation::kStep;
    if (tl.pours_in(sim.time(), next)) sim.pour();
    sim.step(driver.sample(next), tl.drink_rate_at(next));
  }
}

FrameState timeline_frame(const Timeline& tl, const Params& base, double t) {
  Simulation sim(tl.params_at(0, base));
  sim.settle_bubbles(4.0);
  TimelineDriver driver(tl, sim.vessel().r_outer.front());
  play_timeline(sim, driver, tl, base, t);
  return sim.frame();
}

}  // namespace draught
