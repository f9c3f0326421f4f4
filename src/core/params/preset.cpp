#include "core/params/preset.hpp"

#include "core/io/files.hpp"
#include "core/params/json_input.hpp"
#include "core/text/echo.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace draught {

using nlohmann::json;

namespace {

void collect(const json& obj, const std::string& prefix, const std::string& file, Preset& out) {
  for (auto& [key, val] : obj.items()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    bool is_group = false;
    for (auto& d : param_table()) is_group |= d.path.rfind(path + ".", 0) == 0;
    if (const ParamDesc* d = find_param(path)) {
      out.values.emplace_back(d, param_value_from_json(*d, val, file, "params." + d->path));
    } else if (is_group) {
      if (!val.is_object())
        throw InputError(file + ": field 'params." + path + "': expected an object of " + path +
                         ".* parameters, got " + short_dump(val));
      collect(val, path, file, out);
    } else {
      throw InputError(file + ": field 'params." + path + "': " + unknown_param_message(path));
    }
  }
}

std::string group_of(const std::string& path) { return path.substr(0, path.find('.')); }

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
  for (auto& [key, val] : j.items()) {
    static const char* known[] = {"draught_preset", "kind", "name", "description", "suggested_glass", "params"};
    if (std::find_if(std::begin(known), std::end(known), [&, &key = key](const char* k) { return key == k; }) == std::end(known))
      throw InputError(file + ": field '" + key +
                       "': unknown key, expected one of draught_preset, kind, name, description, "
                       "suggested_glass, params");
  }
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
    collect(j["params"], "", file, p);
  }
  for (auto& [d, v] : p.values) {
    const std::string g = group_of(d->path);
    const bool drink_group = g == "liquid" || g == "foam" || g == "bubbles";
    if ((p.kind == "glass" && g != "glass") || (p.kind == "drink" && !drink_group))
      throw InputError(file + ": field 'params." + d->path + "': a " + p.kind + " preset may set only " +
                       (p.kind == "glass" ? "glass.*" : "liquid.*, foam.* and bubbles.*") + " parameters (use kind \"scene\")");
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

std::vector<Preset> list_presets() {
  std::vector<Preset> out;
  for (auto& dir : preset_dirs()) {
    for (const char* sub : {"glasses", "drinks", "scenes"}) {
      std::error_code ec;
      std::vector<std::filesystem::path> files;
      for (auto& e : std::filesystem::directory_iterator(dir / sub, ec))
        if (e.path().extension() == ".json") files.push_back(e.path());
      std::sort(files.begin(), files.end());
      for (auto& f : files) out.push_back(load_preset(f));
    }
    if (!out.empty()) break;  // the first directory that has presets wins
  }
  return out;
}

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
    ParamValue v = get_param(p, d);
    json val;
    std::visit(
        [&](auto&& x) {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, glm::vec3>) val = {x.x, x.y, x.z};
          else if constexpr (std::is_same_v<T, Curve>) {
            val = json::array();
            for (auto& q : x) val.push_back({q.x, q.y});
          } else val = x;
        },
        v);
    params[g][d.path.substr(g.size() + 1)] = val;
  }
  j["params"] = params;
  return j.dump(2) + "\n";
}

void save_preset(const std::filesystem::path& path, const std::string& json_text) {
  parse_preset(json_text, path.string());  // never write what we could not load back
  write_file_atomic(path, json_text);
}

}  // namespace draught

namespace draught {

namespace {
std::pair<const ParamDesc*, ParamValue> parse_assignment(const std::string& flag, const std::string& text) {
  auto eq = text.find('=');
  if (eq == std::string::npos)
    throw InputError(flag + " " + text + ": expected path=value, e.g. " + flag + " liquid.fill=0.8");
  const std::string path = text.substr(0, eq);
  const ParamDesc* d = find_param(path);
  if (!d) throw InputError(flag + " " + text + ": " + unknown_param_message(path));
  try {
    return {d, parse_param_text(*d, text.substr(eq + 1))};
  } catch (const ParamError& e) {
    throw InputError(flag + " " + text + ": field '" + e.field + "': expected " + e.expected);
  }
}
}  // namespace

Params resolve_scene(const SceneRequest& req, std::string* log) {
  const Preset drink = load_preset(find_preset(req.preset, "drink"));
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
  std::vector<std::pair<const ParamDesc*, ParamValue>> overrides;
  for (const auto& c : req.camera) {
    auto eq = c.find('=');
    const std::string key = c.substr(0, eq);
    if (eq == std::string::npos || (key != "eye" && key != "target" && key != "vfov"))
      throw InputError("--camera " + c + ": expected eye=x,y,z, target=x,y,z or vfov=degrees");
    overrides.push_back(parse_assignment("--camera", "camera." + c));
    if (key != "vfov") overrides.push_back(parse_assignment("--camera", "camera.auto_frame=false"));
  }
  for (const auto& s : req.sets) overrides.push_back(parse_assignment("--set", s));
  // Everything is valid: now apply, in order.
  Params p = default_params();
  if (!scene_sets_glass) apply_preset(glass, p);
  apply_preset(drink, p);
  for (auto& [d, v] : overrides) set_param(p, *d, v);
  if (log) {
    *log += "preset: " + drink.name + " (" + drink.file + ")\n";
    if (!scene_sets_glass) *log += "glass: " + glass.name + " (" + glass.file + ")\n";
  }
  return p;
}

}  // namespace draught
