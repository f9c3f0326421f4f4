#include "editor.hpp"

#include "core/io/files.hpp"
#include "core/params/preset.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>

namespace draught::viewer {

namespace {

std::string label_of(const Preset& p) {
  return p.name.empty() ? std::filesystem::path(p.file).stem().string() : p.name;
}

// find_preset takes a bare word for a preset name; a file typed in the UI is always a path.
std::string as_path(const std::string& text) {
  if (text.find('/') != std::string::npos || text.ends_with(".json")) return text;
  return "./" + text;
}

}  // namespace

// The same resolution as the CLI (glass preset, then drink or scene, a scene's objects), plus
// the names to show. Throws InputError naming the file and field.
Editor::State Editor::resolve_named(const std::string& drink, const std::string& glass) {
  const Preset d = load_preset(find_preset(drink, "drink"));
  SceneRequest req;
  req.preset = drink;
  req.glass = glass;
  State st{resolve_scene_objects(req), drink, glass, label_of(d), ""};
  // What resolve_scene used: "" when a scene brings its own glass.
  if (st.glass.empty()) st.glass = !d.suggested_glass.empty() ? d.suggested_glass : d.kind == "scene" ? "" : "pint";
  st.glass_label = st.glass.empty() ? "(the scene's)" : label_of(load_preset(find_preset(st.glass, "glass")));
  return st;
}

Editor::Editor(const std::string& drink, const std::string& glass)
    : now_(resolve_named(drink, glass)), committed_(now_) {}

void Editor::select(int object) {
  const int last = std::max(0, int(now_.scene.objects.size()) - 1);
  now_.scene.selected = committed_.scene.selected = std::clamp(object, 0, last);
}

void Editor::change(const Scene& s) {
  const int selected = now_.scene.selected;
  now_.scene = s;
  select(selected);
  pending_ = true;
  ++revision_;
}

void Editor::restore(State st) {
  const int selected = now_.scene.selected;
  now_ = std::move(st);
  select(selected);
}

void Editor::settle(bool busy) {
  if (!pending_ || busy) return;
  history_.push_back(committed_);
  if (history_.size() > kHistory) history_.pop_front();
  committed_ = now_;
  pending_ = false;
}

bool Editor::undo() {
  settle(false);
  if (history_.empty()) return false;
  restore(history_.back());
  committed_ = now_;
  history_.pop_back();
  ++revision_;
  status_ = {"undone (" + std::to_string(history_.size()) + " more)", false};
  return true;
}

void Editor::replace(const State& st) {
  settle(false);
  restore(st);
  pending_ = true;
  ++revision_;
  settle(false);
}

bool Editor::fail(const std::string& message) {
  status_ = {message, true};
  return false;
}

bool Editor::resolve(const std::string& drink, const std::string& glass, const char* what) {
  try {
    replace(resolve_named(drink, glass));
    status_ = {std::string(what) + ": " + now_.drink_label + " in " + now_.glass_label, false};
    return true;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

bool Editor::choose_drink(const std::string& name_or_path) { return resolve(name_or_path, "", "drink"); }

bool Editor::choose_glass(const std::string& name_or_path) { return resolve(now_.drink, name_or_path, "glass"); }

bool Editor::load(const std::string& path_text) {
  if (path_text.empty()) return fail("type the path of a preset file to load");
  const std::string path = as_path(path_text);
  std::string kind;
  try {
    kind = load_preset(path).kind;  // validates the whole file before anything changes
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  const bool ok = kind == "glass" ? resolve(now_.drink, path, "loaded") : resolve(path, "", "loaded");
  if (ok) {
    file_ = path_text;
    file_kind_ = kind;
    status_.text = "loaded " + path_text + ": " + now_.drink_label + " in " + now_.glass_label;
  }
  return ok;
}

bool Editor::use_environment(const std::string& path) {
  if (path.empty()) return fail("type the path of an HDR environment (.hdr or .exr) or a shipped name");
  State st = now_;
  try {
    set_param(st.scene, parse_param_ref(st.scene, "env.image"), ParamValue(path));  // reads the file
    set_param(st.scene, parse_param_ref(st.scene, "env.mode"), ParamValue(std::string("image")));
  } catch (const ParamError& e) {
    return fail("env.image: expected " + e.expected);
  }
  replace(st);
  status_ = {"environment: " + path, false};
  return true;
}

bool Editor::save_as(const std::string& path_text, const std::string& kind) {
  if (path_text.empty()) return fail("type the path of the file to save");
  std::vector<std::string> groups;
  if (kind == "drink") groups = {"liquid", "foam", "bubbles"};
  else if (kind == "glass") groups = {"glass"};
  else if (kind != "scene") return fail("unknown preset kind '" + kind + "': expected scene, drink or glass");
  const std::filesystem::path path = as_path(path_text);
  try {
    // A scene is saved whole (every object and its placement); a drink or a glass is the
    // selected object's.
    save_preset(path, kind == "scene"
                          ? scene_preset_json(now_.scene, path.stem().string(), "saved from draught-viewer")
                          : preset_json(document(), kind, path.stem().string(), "saved from draught-viewer", groups));
  } catch (const std::exception& e) {
    return fail(e.what());
  }
  file_ = path_text;
  file_kind_ = kind;
  status_ = {"saved " + path_text + " (" + kind + ")", false};
  return true;
}

bool Editor::save() {
  if (file_.empty()) return fail("nothing loaded or saved yet: use Save as");
  return save_as(file_, file_kind_);
}

}  // namespace draught::viewer
