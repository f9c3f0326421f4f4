#include "core/params/preset.hpp"

#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/vessel/vessel.hpp"
#include "core/text/echo.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace draught {

using nlohmann::json;

namespace {

// The parameters in `obj` (nested by group); `field` is where obj lies in the file
// ("params." or "objects[2].params.").
void collect(const json& obj, const std::string& prefix, const std::string& file, const std::string& field,
             PresetValues& out) {
  for (auto& [key, val] : obj.items()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    bool is_group = false;
    for (auto& d : param_table()) is_group |= d.path.rfind(path + ".", 0) == 0;
    if (const ParamDesc* d = find_param(path)) {
      out.emplace_back(d, param_value_from_json(*d, val, file, field + d->path));
    } else if (is_group) {
      if (!val.is_object())
        throw InputError(file + ": field '" + field + path + "': expected an object of " + path +
                         ".* parameters, got " + short_dump(val));
      collect(val, path, file, field, out);
    } else {
      throw InputError(file + ": field '" + field + path + "': " + unknown_param_message(path));
    }
  }
}

std::string group_of(const std::string& path) { return path.substr(0, path.find('.')); }

std::string groups_of(ParamScope scope) {
  std::string out;
  for (auto& d : param_table()) {
    const std::string g = group_of(d.path) + ".*";
    if (d.scope == scope && out.find(g) == std::string::npos) out += (out.empty() ? "" : ", ") + g;
  }
  return out;
}

void check_keys(const json& obj, const std::string& file, const std::string& where,
                std::initializer_list<const char*> keys) {
  for (auto& [key, val] : obj.items()) {
    if (std::find_if(keys.begin(), keys.end(), [&, &key = key](const char* k) { return key == k; }) != keys.end())
      continue;
    std::string list;
    for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
    throw InputError(file + ": field '" + where + key + "': unknown key, expected one of " + list);
  }
}

PresetObject parse_object(const json& o, const std::string& file, const std::string& at) {
  if (!o.is_object())
    throw InputError(file + ": field '" + at + "': expected an object with name, glass, drink, position, yaw, "
                     "params; got " + short_dump(o));
  check_keys(o, file, at + ".", {"name", "kind", "glass", "drink", "position", "yaw", "params", "droplets", "pointcloud"});
  PresetObject obj;
  if (o.contains("kind")) {
    const json& k = o["kind"];
    const std::string kind = k.is_string() ? k.get<std::string>() : "";
    if (kind != "vessel" && kind != "droplets" && kind != "pointcloud")
      throw InputError(file + ": field '" + at + ".kind': expected \"vessel\" (the default), \"droplets\" or "
                       "\"pointcloud\", got " + short_dump(k));
    if (kind != "vessel") {
      const std::string own = kind;  // the key that holds this kind's parameters
      for (const char* key : {"glass", "drink", "params"})
        if (o.contains(key))
          throw InputError(file + ": field '" + at + "." + key + "': a " + kind + " object has no " + key +
                           " (its parameters are in " + at + "." + own + ")");
    }
    if (kind == "droplets")
      obj.droplets = o.contains("droplets") ? parse_droplet_params(o["droplets"], file, at + ".droplets")
                                            : DropletParams{};
    if (kind == "pointcloud")
      obj.cloud = o.contains("pointcloud") ? parse_point_cloud_params(o["pointcloud"], file, at + ".pointcloud",
                                                                      std::filesystem::path(file).parent_path().string())
                                           : PointCloudParams{};
  }
  if (o.contains("droplets") && !obj.droplets)
    throw InputError(file + ": field '" + at + ".droplets': only an object of \"kind\": \"droplets\" has droplets");
  if (o.contains("pointcloud") && !obj.cloud)
    throw InputError(file + ": field '" + at + ".pointcloud': only an object of \"kind\": \"pointcloud\" has "
                     "point-cloud parameters");
  auto str = [&](const char* key, bool required) -> std::string {
    const std::string f = at + "." + key;
    if (!o.contains(key)) {
      if (required) throw InputError(file + ": field '" + f + "': missing, expected a string");
      return "";
    }
    if (!o[key].is_string() || o[key].get<std::string>().empty())
      throw InputError(file + ": field '" + f + "': expected a non-empty string, got " + short_dump(o[key]));
    return o[key].get<std::string>();
  };
  obj.name = str("name", true);
  obj.glass = str("glass", false);
  obj.drink = str("drink", false);
  if (o.contains("position")) {
    const json& p = o["position"];
    const std::string expected =
        "expected [x, y, z] in metres: x and z in [-5, 5], y (the foot above the floor) in [0, 1]";
    if (!p.is_array() || p.size() != 3)
      throw InputError(file + ": field '" + at + ".position': " + expected + ", got " + short_dump(p));
    for (int i = 0; i < 3; ++i) {
      const json& c = p[size_t(i)];
      const double lo = i == 1 ? 0.0 : -5.0, hi = i == 1 ? 1.0 : 5.0;
      if (!c.is_number() || !(c.get<double>() >= lo && c.get<double>() <= hi))
        throw InputError(file + ": field '" + at + ".position': " + expected + ", got " + short_dump(p));
      obj.placement.position[i] = c.get<float>();
    }
  }
  if (o.contains("yaw")) {
    const json& y = o["yaw"];
    if (!y.is_number() || !(y.get<double>() >= -360.0 && y.get<double>() <= 360.0))
      throw InputError(file + ": field '" + at + ".yaw': expected a number of degrees in [-360, 360], got " +
                       short_dump(y));
    obj.placement.yaw = y.get<float>();
  }
  if (o.contains("params")) {
    const json& params = o["params"];
    if (!params.is_object())
      throw InputError(file + ": field '" + at + ".params': expected an object of parameter groups (" +
                       groups_of(ParamScope::Vessel) + "), got " + short_dump(params));
    collect(params, "", file, at + ".params.", obj.values);
    for (auto& [d, v] : obj.values)
      if (d->scope != ParamScope::Vessel)
        throw InputError(file + ": field '" + at + ".params." + d->path + "': " + group_of(d->path) +
                         ".* belongs to the whole scene: set it in the preset's top-level params (an object may set " +
                         groups_of(ParamScope::Vessel) + ")");
  }
  return obj;
}

}  // namespace

Preset parse_preset(const std::string& text, const std::string& file) {
  const json j = parse_json_file_text(text, file);
  if (!j.is_object()) throw InputError(file + ": expected a JSON object at the top level");
  Preset p;
  p.file = file;
  auto str_field = [&](const char* key, bool required) -> std::string {
    if (!j.contains(key)) {
      if (required) throw InputError(file + ": field '" + key + "': missing, expected a string");
      return "";
    }
    if (!j[key].is_string()) throw InputError(file + ": field '" + key + "': expected a string, got " + short_dump(j[key]));
    return j[key].get<std::string>();
  };
  check_keys(j, file, "", {"draught_preset", "kind", "name", "description", "suggested_glass", "params", "objects"});
  if (j.contains("draught_preset") && j["draught_preset"] != kPresetFormat)
    throw InputError(file + ": field 'draught_preset': expected format " + std::to_string(kPresetFormat) +
                     ", got " + short_dump(j["draught_preset"]));
  p.kind = str_field("kind", true);
  if (p.kind != "glass" && p.kind != "drink" && p.kind != "scene")
    throw InputError(file + ": field 'kind': expected \"glass\", \"drink\" or \"scene\", got " + quote_input(p.kind));
  p.name = str_field("name", true);
  p.description = str_field("description", false);
  p.suggested_glass = str_field("suggested_glass", false);
  if (!p.suggested_glass.empty() && p.kind == "glass")
    throw InputError(file + ": field 'suggested_glass': only drinks and scenes suggest a glass");
  if (j.contains("params")) {
    if (!j["params"].is_object())
      throw InputError(file + ": field 'params': expected an object of parameter groups, got " +
                       short_dump(j["params"]));
    collect(j["params"], "", file, "params.", p.values);
  }
  for (auto& [d, v] : p.values) {
    const std::string g = group_of(d->path);
    const bool drink_group = g == "liquid" || g == "foam" || g == "bubbles";
    if ((p.kind == "glass" && g != "glass") || (p.kind == "drink" && !drink_group))
      throw InputError(file + ": field 'params." + d->path + "': a " + p.kind + " preset may set only " +
                       (p.kind == "glass" ? "glass.*" : "liquid.*, foam.* and bubbles.*") + " parameters (use kind \"scene\")");
  }
  if (j.contains("objects")) {
    const json& objects = j["objects"];
    if (p.kind != "scene")
      throw InputError(file + ": field 'objects': only a scene preset places objects (kind \"scene\"), this is a " +
                       p.kind + " preset");
    if (!objects.is_array() || objects.empty())
      throw InputError(file + ": field 'objects': expected an array of 1 to " + std::to_string(kMaxSceneObjects) +
                       " objects, got " + short_dump(objects));
    if (objects.size() > size_t(kMaxSceneObjects))
      throw InputError(file + ": field 'objects': expected at most " + std::to_string(kMaxSceneObjects) +
                       " objects, got " + std::to_string(objects.size()));
    for (size_t i = 0; i < objects.size(); ++i) {
      const std::string at = "objects[" + std::to_string(i) + "]";
      p.objects.push_back(parse_object(objects[i], file, at));
      if (p.objects[i].cloud) {
        int clouds = 0;
        for (size_t k = 0; k <= i; ++k) clouds += p.objects[k].cloud ? 1 : 0;
        if (clouds > kMaxCloudObjects)
          throw InputError(file + ": field '" + at + ".kind': a scene holds at most " + std::to_string(kMaxCloudObjects) +
                           " point clouds");
      }
      if (p.objects[i].droplets)
        for (size_t k = 0; k < i; ++k)
          if (p.objects[k].droplets)
            throw InputError(file + ": field '" + at + ".kind': a scene holds at most one droplets object (also objects[" +
                             std::to_string(k) + "])");
      for (size_t k = 0; k < i; ++k)
        if (p.objects[k].name == p.objects[i].name)
          throw InputError(file + ": field '" + at + ".name': expected a name no other object has, got \"" +
                           p.objects[i].name + "\" (also objects[" + std::to_string(k) + "])");
    }
    if (!p.suggested_glass.empty())
      throw InputError(file + ": field 'suggested_glass': a scene with objects gives each object its glass "
                       "(objects[N].glass)");
    for (auto& [d, v] : p.values)
      if (d->scope != ParamScope::Scene)
        throw InputError(file + ": field 'params." + d->path + "': a scene with objects sets " + group_of(d->path) +
                         ".* per object (objects[N].params); its own params may set only " +
                         groups_of(ParamScope::Scene));
  }
  return p;
}

Preset load_preset(const std::filesystem::path& path) { return parse_preset(read_text_file(path), path.string()); }

void apply_preset(const Preset& p, Params& params) {
  for (auto& [d, v] : p.values) set_param(params, *d, v);  // values were validated when parsed
}

std::vector<std::filesystem::path> preset_dirs() {
  std::vector<std::filesystem::path> dirs;
  if (const char* env = std::getenv("DRAUGHT_PRESET_DIR"); env && *env) dirs.emplace_back(env);
  dirs.emplace_back(DRAUGHT_SOURCE_PRESET_DIR);
  return dirs;
}

std::filesystem::path find_preset(const std::string& name, const std::string& kind) {
  if (name.find('/') != std::string::npos || name.ends_with(".json")) {
    std::error_code ec;  // a name too long for a path is no file either
    if (!std::filesystem::exists(name, ec)) throw InputError(shorten(name, kEchoPathBytes) + ": no such preset file");
    return name;
  }
  std::string tried;
  for (auto& dir : preset_dirs()) {
    for (const std::string& sub : {kind == "glass" ? std::string("glasses") : kind + "s", std::string("scenes")}) {
      auto p = dir / sub / (name + ".json");
      std::error_code ec;
      if (std::filesystem::exists(p, ec)) return p;
      tried += (tried.empty() ? "" : ", ") + p.string();
    }
  }
  if (name.size() > kEchoBytes) tried = "the preset folders";  // a long name (from a file?) is not repeated
  throw InputError("no " + kind + " preset named '" + shorten(name) + "' (looked for " + tried +
                   "); `draught presets` lists them");
}

std::vector<Preset> list_presets(std::vector<std::string>* broken) {
  std::vector<Preset> out;
  for (auto& dir : preset_dirs()) {
    for (const char* sub : {"glasses", "drinks", "scenes"}) {
      std::error_code ec;
      std::vector<std::filesystem::path> files;
      for (auto& e : std::filesystem::directory_iterator(dir / sub, ec))
        if (e.path().extension() == ".json") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (auto& f : files) {
        try {
          out.push_back(load_preset(f));
        } catch (const InputError& e) {
          if (!broken) throw;
          broken->push_back(e.what());
        }
      }
    }
    if (!out.empty() || (broken && !broken->empty())) break;  // the first directory that has presets wins
  }
  return out;
}

namespace {
json value_json(const ParamValue& v) {
  json val;
  std::visit(
      [&](auto&& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, glm::vec3>) val = {shortest_double(x.x), shortest_double(x.y), shortest_double(x.z)};
        else if constexpr (std::is_same_v<T, Curve>) {
          val = json::array();
          for (auto& q : x) val.push_back({shortest_double(q.x), shortest_double(q.y)});
        } else if constexpr (std::is_same_v<T, float>) val = shortest_double(x);
        else val = x;
      },
      v);
  return val;
}

// {"group": {"name": value}} for the rows of one scope.
json groups_json(const Params& p, ParamScope scope) {
  json params = json::object();
  for (auto& d : param_table()) {
    if (d.scope != scope) continue;
    const std::string g = group_of(d.path);
    params[g][d.path.substr(g.size() + 1)] = value_json(get_param(p, d));
  }
  return params;
}
}  // namespace

std::string preset_json(const Params& p, const std::string& kind, const std::string& name,
                        const std::string& description, const std::vector<std::string>& groups) {
  json j = json::object();
  j["draught_preset"] = kPresetFormat;
  j["kind"] = kind;
  j["name"] = name;
  if (!description.empty()) j["description"] = description;
  json params = json::object();
  for (auto& d : param_table()) {
    const std::string g = group_of(d.path);
    if (!groups.empty() && std::find(groups.begin(), groups.end(), g) == groups.end()) continue;
    params[g][d.path.substr(g.size() + 1)] = value_json(get_param(p, d));
  }
  j["params"] = params;
  return j.dump(2) + "\n";
}

std::string scene_preset_json(const Scene& scene, const std::string& name, const std::string& description) {
  if (scene.objects.size() <= 1) return preset_json(vessel_document(scene, 0), "scene", name, description, {});
  json j = json::object();
  j["draught_preset"] = kPresetFormat;
  j["kind"] = "scene";
  j["name"] = name;
  if (!description.empty()) j["description"] = description;
  j["params"] = groups_json(vessel_document(scene, 0), ParamScope::Scene);
  // Each object with every vessel value written out: what was edited is kept as it is,
  // independent of the glass and drink presets it came from.
  json objects = json::array();
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const Placement& at = o.placement;
    if (const PointCloudObject* c = as_cloud(o)) {
      objects.push_back({{"name", o.name},
                         {"kind", "pointcloud"},
                         {"position", {shortest_double(at.position.x), shortest_double(at.position.y),
                                       shortest_double(at.position.z)}},
                         {"yaw", shortest_double(at.yaw)},
                         {"pointcloud", point_cloud_params_json(c->params)}});
      continue;
    }
    if (const DropletsObject* d = as_droplets(o)) {
      objects.push_back({{"name", o.name},
                         {"kind", "droplets"},
                         {"position", {shortest_double(at.position.x), shortest_double(at.position.y),
                                       shortest_double(at.position.z)}},
                         {"yaw", shortest_double(at.yaw)},
                         {"droplets", droplet_params_json(d->params)}});
      continue;
    }
    objects.push_back({{"name", o.name},
                       {"position", {shortest_double(at.position.x), shortest_double(at.position.y),
                                     shortest_double(at.position.z)}},
                       {"yaw", shortest_double(at.yaw)},
                       {"params", groups_json(vessel_document(scene, int(i)), ParamScope::Vessel)}});
  }
  j["objects"] = objects;
  return j.dump(2) + "\n";
}

void save_preset(const std::filesystem::path& path, const std::string& json_text) {
  parse_preset(json_text, path.string());  // never write what we could not load back
  write_file_atomic(path, json_text);
}

}  // namespace draught

namespace draught {

std::vector<std::string> preset_names(const std::string& kind) {
  std::vector<std::string> names;
  const std::string sub = kind == "glass" ? "glasses" : kind + "s";
  for (auto& dir : preset_dirs()) {
    std::error_code ec;
    for (auto& e : std::filesystem::directory_iterator(dir / sub, ec))
      if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

namespace {

// An object's glass or drink preset: a name in the preset directories' <kind>s/ folder,
// or a path (relative to the scene file).
Preset load_object_preset(const Preset& scene, const std::string& name, const std::string& kind,
                          const std::string& field) {
  // A control character names no preset (a NUL would cut the path short where the file
  // system reads it: "glasses/\u0000pint" is the folder).
  if (std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
    throw InputError(scene.file + ": field '" + field + "': expected a " + kind + " preset's name or path, got " +
                     quote_input(name));
  std::filesystem::path path;
  if (name.find('/') != std::string::npos || name.ends_with(".json")) {
    path = name;
    if (path.is_relative()) path = std::filesystem::path(scene.file).parent_path() / path;
    if (!std::filesystem::exists(path))
      throw InputError(scene.file + ": field '" + field + "': no such " + kind + " preset file " + path.string());
  } else {
    const std::string sub = kind == "glass" ? "glasses" : kind + "s";
    for (auto& dir : preset_dirs())
      if (std::filesystem::exists(dir / sub / (name + ".json"))) {
        path = dir / sub / (name + ".json");
        break;
      }
    if (path.empty()) {
      const std::vector<std::string> names = preset_names(kind);
      std::string list;
      for (auto& n : names) list += (list.empty() ? "" : ", ") + n;
      const std::string near = nearest_choice(name, names);
      throw InputError(scene.file + ": field '" + field + "': expected one of " + list + " (a " + kind +
                       " preset), got \"" + name + "\"" + (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
    }
  }
  Preset p = load_preset(path);
  if (p.kind != kind)
    throw InputError(scene.file + ": field '" + field + "': expected a " + kind + " preset, but " + p.file +
                     " is a " + p.kind + " preset");
  return p;
}

std::string metres(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f m", v);
  return buf;
}

}  // namespace

void check_footprints(const Scene& s, const std::string& where) {
  struct Foot {
    size_t index;
    glm::dvec2 at;
    double radius;
  };
  std::vector<Foot> feet;
  for (size_t i = 0; i < s.objects.size(); ++i)
    if (const VesselObject* v = as_vessel(s.objects[i])) {
      const glm::vec3 p = s.objects[i].placement.position;
      feet.push_back({i, glm::dvec2(p.x, p.z), build_vessel(v->params.glass).bound_radius});
    }
  for (size_t a = 0; a < feet.size(); ++a)
    for (size_t b = a + 1; b < feet.size(); ++b) {
      const double apart = glm::length(feet[a].at - feet[b].at), need = feet[a].radius + feet[b].radius;
      if (apart >= need) continue;
      auto label = [&](const Foot& f) {
        return "objects[" + std::to_string(f.index) + "] '" + s.objects[f.index].name + "'";
      };
      throw InputError(where + ": " + label(feet[a]) + " and " + label(feet[b]) +
                       " overlap: their glasses would interpenetrate (widest radii " + metres(feet[a].radius) +
                       " and " + metres(feet[b].radius) + ", so their positions need at least " + metres(need) +
                       " between them, got " + metres(apart) + ")");
    }
}

Scene scene_from_preset(const Preset& preset, std::string* log) {
  if (preset.objects.empty())
    throw std::logic_error("scene_from_preset: " + preset.file + " places no objects");
  Scene scene;
  Params scene_doc = default_params();
  apply_preset(preset, scene_doc);  // the scene's own groups (validated when parsed)
  scene.params = scene_doc;
  std::string used;
  for (size_t i = 0; i < preset.objects.size(); ++i) {
    const PresetObject& o = preset.objects[i];
    const std::string at = "objects[" + std::to_string(i) + "]";
    if (o.cloud) {
      scene.objects.push_back(SceneObject{o.name, o.placement, PointCloudObject{*o.cloud}});
      used += at + " " + o.name + ": point cloud\n";
      continue;
    }
    if (o.droplets) {
      scene.objects.push_back(SceneObject{o.name, o.placement, DropletsObject{*o.droplets}});
      used += at + " " + o.name + ": droplets\n";
      continue;
    }
    std::optional<Preset> drink;
    if (!o.drink.empty()) drink = load_object_preset(preset, o.drink, "drink", at + ".drink");
    const std::string glass_name = !o.glass.empty()                          ? o.glass
                                   : drink && !drink->suggested_glass.empty() ? drink->suggested_glass
                                                                             : "pint";
    const Preset glass = load_object_preset(preset, glass_name, "glass", at + (o.glass.empty() ? ".drink" : ".glass"));
    VesselParams v;
    for (auto& [d, val] : glass.values) set_param(v, *d, val);
    if (drink)
      for (auto& [d, val] : drink->values) set_param(v, *d, val);
    for (auto& [d, val] : o.values) set_param(v, *d, val);
    scene.objects.push_back(SceneObject{o.name, o.placement, VesselObject{v}});
    used += at + " " + o.name + ": glass " + glass.name + " (" + glass.file + ")" +
            (drink ? ", drink " + drink->name + " (" + drink->file + ")" : std::string()) + "\n";
  }
  check_footprints(scene, preset.file);
  if (log) *log += used;
  return scene;
}

namespace {

// "path=value" of --set or --camera against the scene: the path may address one object.
std::pair<ParamRef, ParamValue> parse_assignment(const Scene& scene, const std::string& flag, const std::string& text) {
  const std::string shown = flag + " " + shorten(text);  // capped: a pasted page is not echoed
  auto eq = text.find('=');
  if (eq == std::string::npos)
    throw InputError(shown + ": expected path=value, e.g. " + flag + " liquid.fill=0.8");
  const std::string path = text.substr(0, eq);
  auto fail = [&](const std::string& expected) -> InputError {
    return InputError(shown + ": field '" + shorten(path) + "': expected " + expected);
  };
  ParamRef ref;
  try {
    const ObjectPath split = split_object_path(path);
    if (!find_param(split.param))
      throw InputError(shown + ": " + unknown_param_message(std::string(split.param)));
    ref = parse_param_ref(scene, path);
  } catch (const ParamError& e) {
    throw fail(e.expected);
  }
  try {
    return {ref, parse_param_text(*ref.desc, text.substr(eq + 1))};
  } catch (const ParamError& e) {
    throw fail(e.expected);
  }
}
}  // namespace

Scene resolve_scene_objects(const SceneRequest& req, std::string* log) {
  const Preset drink = load_preset(find_preset(req.preset, "drink"));
  std::string used;
  Scene scene;
  if (!drink.objects.empty()) {
    if (!req.glass.empty())
      throw InputError("--glass " + req.glass + ": the scene '" + drink.name + "' (" + drink.file +
                       ") places its own glasses; leave out --glass (change one object's glass with --set "
                       "objects[N].glass.*, or in the scene file)");
    std::string objects_log;
    scene = scene_from_preset(drink, &objects_log);
    used = "preset: " + drink.name + " (" + drink.file + "), " + std::to_string(scene.objects.size()) +
           " objects\n" + objects_log;
  } else {
    const std::string glass_name = !req.glass.empty()                ? req.glass
                                   : !drink.suggested_glass.empty() ? drink.suggested_glass
                                                                    : "pint";
    // A scene that sets its own glass and names none keeps it.
    const bool scene_sets_glass = drink.kind == "scene" && req.glass.empty() && drink.suggested_glass.empty();
    if (drink.kind != "drink" && drink.kind != "scene")
      throw InputError(drink.file + ": field 'kind': expected \"drink\" or \"scene\" for --preset, got \"" +
                       drink.kind + "\"");
    Preset glass;
    if (!scene_sets_glass) {
      glass = load_preset(find_preset(glass_name, "glass"));
      if (glass.kind != "glass")
        throw InputError(glass.file + ": field 'kind': expected \"glass\" for --glass, got \"" + glass.kind + "\"");
    }
    Params p = default_params();
    if (!scene_sets_glass) apply_preset(glass, p);
    apply_preset(drink, p);
    scene = single_glass_scene(p);
    used = "preset: " + drink.name + " (" + drink.file + ")\n";
    if (!scene_sets_glass) used += "glass: " + glass.name + " (" + glass.file + ")\n";
  }
  // Every override is checked against the scene before any is applied.
  std::vector<std::pair<ParamRef, ParamValue>> overrides;
  // `--camera eye=.. target=..` as separate words, or quoted as one as the help shows it.
  std::vector<std::string> camera_words;
  for (const auto& given : req.camera) {
    std::istringstream words(given);
    for (std::string w; words >> w;) camera_words.push_back(w);
  }
  for (const auto& c : camera_words) {
    auto eq = c.find('=');
    const std::string key = c.substr(0, eq);
    if (eq == std::string::npos || (key != "eye" && key != "target" && key != "vfov"))
      throw InputError("--camera " + c + ": expected eye=x,y,z, target=x,y,z or vfov=degrees");
    overrides.push_back(parse_assignment(scene, "--camera", "camera." + c));
    if (key != "vfov") overrides.push_back(parse_assignment(scene, "--camera", "camera.auto_frame=false"));
  }
  for (const auto& s : req.sets) overrides.push_back(parse_assignment(scene, "--set", s));
  Scene out = scene;
  for (auto& [ref, v] : overrides) set_param(out, ref, v);
  if (out.objects.size() > 1 && !req.sets.empty()) check_footprints(out, "--set");
  if (log) *log += used;
  return out;
}

Params resolve_scene(const SceneRequest& req, std::string* log) {
  return vessel_document(resolve_scene_objects(req, log), 0);
}

}  // namespace draught
